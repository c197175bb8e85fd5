"""A throwaway `fsdb serve` on a free loopback port with an empty database in a temp folder.

The binary is $FSDB_BINARY (ctest sets it) or build/fsdb of the repository."""
import os
import subprocess
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[3]


def binary() -> str:
    return os.environ.get("FSDB_BINARY") or str(REPO / "build" / "fsdb")


class Server:
    def __init__(self, *args: str):
        self.dir = tempfile.TemporaryDirectory(prefix="fsdb-python-")
        self.process = subprocess.Popen(
            [binary(), "--log-level", "warn", "serve", "--port", "0", "--db", os.path.join(self.dir.name, "db.sqlite"),
             *args],
            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        line = self.process.stdout.readline()
        if not line.startswith("listening on "):
            self.stop()
            raise RuntimeError(f"fsdb serve did not start: {line!r}")
        self.url = line.split()[2]

    def stop(self) -> None:
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.process.kill()
        self.process.stdout.close()
        self.dir.cleanup()
