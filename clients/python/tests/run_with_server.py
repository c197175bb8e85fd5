"""Runs a script against a throwaway fsdb serve (tests/server.py): FSDB_URL is set for it.
Usage: run_with_server.py SCRIPT [ARGS...]"""
import os
import subprocess
import sys

from server import Server

server = Server()
try:
    code = subprocess.call([sys.executable, *sys.argv[1:]], env={**os.environ, "FSDB_URL": server.url})
finally:
    server.stop()
sys.exit(code)
