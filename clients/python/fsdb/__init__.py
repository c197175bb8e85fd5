"""A Python client for the fsdb fuzzy shape database server (standard library only).

    import fsdb
    client = fsdb.Client("http://127.0.0.1:8080")
    bolt = client.parts.create({"name": "bolt", "params": {"a1": 1, "a2": 1, "a3": 3}})
    client.query("find a long part")

Every error answer of the server is raised as FsdbError (status, code, message, path).
"""
from fsdb.client import ROUTES, Client, Collection, FsdbError

__all__ = ["Client", "Collection", "FsdbError", "ROUTES"]
__version__ = "0.1.0"
