"""A tour of fsdb from Python, as the main README walks it with curl: parts, a shape, volumes,
a mesh, the searches in plain words, curves. Run it against a server:

    make serve                                   # in another terminal (or any fsdb serve)
    PYTHONPATH=clients/python python3 clients/python/examples/tour.py [URL]

URL defaults to $FSDB_URL, then http://127.0.0.1:8080. Names are suffixed so the tour can run
twice against one database.
"""
import os
import sys
import time

import fsdb

url = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("FSDB_URL", "http://127.0.0.1:8080")
client = fsdb.Client(url)
tag = str(int(time.time() * 1000) % 10**9)
print("server:", client.health()["version"], "on", client.health()["backend"])

# Parts: superquadrics whose parameters are fuzzy numbers ("about 2", a triangle, a trapezoid).
disc = client.parts.create({"name": "disc-" + tag, "params": {"eps1": 0.2, "eps2": 1, "a1": 2, "a2": 2, "a3": 0.2}})
rod = client.parts.create({"name": "rod-" + tag,
                           "params": {"eps1": 1, "eps2": 1, "a1": 0.2, "a2": 0.2, "a3": {"about": 2, "spread": 0.2},
                                      "kv": {"tri": [0.0, 0.05, 0.1]}}})
print("parts:", disc["id"], rod["id"])

# A shape: the rod standing on the disc, the rod's placement fuzzy ("about 2 units up").
lamp = client.shapes.create({"name": "lamp-" + tag, "tree": {"op": "union", "children": [
    {"part": disc["name"]},
    {"part": rod["name"], "transform": {"translate": [0, 0, {"about": 2, "spread": 0.1}]}}]}})
print("shape:", lamp["id"], "version", lamp["version"], "ETag-checked update:",
      client.shapes.put(lamp["id"], {**lamp["document"], "meta": {"note": "a lamp"}}, if_version=1)["version"])

# Its fuzzy volume: lower and upper volume at each level alpha.
for level in client.shapes.evaluate(lamp["id"], resolution=32, alphas=(0, 0.5, 1))["alphas"]:
    print("  alpha %.1f: lower %.3f, upper %.3f" % (level["alpha"], level["lower_volume"], level["upper_volume"]))
obj = client.mesh(lamp["id"], alpha=0.5, bound="upper", resolution=32)
print("mesh: %d bytes of OBJ, %d vertices" % (len(obj), obj.count(b"\nv ")))
print("membership of the origin:", client.membership(lamp["id"], 0, 0, 0)["upper"])

# Search in plain words, and by structure.
for hit in client.query("find a slightly bent part", limit=3)["results"]:
    print("  %-24s %.3f" % (hit["name"], hit["score"]))
answer = client.query("the union of a flat disc and a long rod", limit=3)
print("search:", answer["search"], [r["name"] for r in answer["results"]])

# Curves: a fuzzy Bezier curve, stored and drawn; fair curves through points.
wave = client.curves.create({"name": "wave-" + tag, "bezier": {"control_points": [
    [0, 0], [1, {"tri": [1.5, 2, 2.5]}], [3, {"tri": [-2.5, -2, -1.5]}], [4, 0]]}})
print("svg: %d characters" % len(client.curves.svg(wave["id"], alpha=0.5)))
print("fair candidates:", len(client.fair_curve([[0, 0], [2, 1], [4, 0], [6, 1]], samples=8)["candidates"]))

# Errors come back as fsdb.FsdbError with the server's code and the path of the bad value.
try:
    client.parts.create({"name": "broken-" + tag, "params": {"a1": -1}})
except fsdb.FsdbError as e:
    print("error:", e.status, e.code, "at", e.path)

# Bulk import: many documents, a batch a request; errors numbered by line.
report = client.bulk_import([{"name": "bolt-%s-%d" % (tag, i), "params": {"a1": 0.5 + i / 10, "a2": 0.5, "a3": 0.5}}
                             for i in range(20)], batch=8)
print("bulk: imported %d, failed %d" % (report["imported"], report["failed"]))
client.shapes.delete(lamp["id"])
print("tour done")
