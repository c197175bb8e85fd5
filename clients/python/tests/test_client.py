"""Every method of fsdb.Client against a real `fsdb serve` (tests/server.py), errors included."""
import unittest

import fsdb
from server import Server

WAVE = [[0, 0], [1, {"tri": [1.5, 2, 2.5]}], [3, {"tri": [-2.5, -2, -1.5]}], [4, 0]]
SADDLE = [[[0, 0, 0], [1, 0, 1], [2, 0, 0]],
          [[0, 1, -1], [1, 1, {"tri": [-0.5, 0, 0.5]}], [2, 1, -1]],
          [[0, 2, 0], [1, 2, 1], [2, 2, 0]]]


def part(name, a1=1.0, **params):
    return {"name": name, "params": {"a1": a1, "a2": 1, "a3": 2, **params}}


class ClientTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.server = Server()
        cls.client = fsdb.Client(cls.server.url)

    @classmethod
    def tearDownClass(cls):
        cls.server.stop()

    def assertFsdbError(self, call, status, code, path=None):
        with self.assertRaises(fsdb.FsdbError) as caught:
            call()
        self.assertEqual((caught.exception.status, caught.exception.code), (status, code), caught.exception)
        if path is not None:
            self.assertEqual(caught.exception.path, path)
        self.assertTrue(caught.exception.message)
        return caught.exception

    def test_service_routes(self):
        c = self.client
        self.assertEqual(c.health()["status"], "ok")
        self.assertIn("/health", c.openapi()["paths"])
        self.assertIn("descriptors", c.vocabulary())
        self.assertTrue(any(o["name"] == "algebraic" for o in c.operators()["operators"]))
        self.assertAlmostEqual(c.evaluate_operator({"name": "algebraic"}, [[0.5, 0.5]], op="intersection")["values"][0], 0.25)
        self.assertFsdbError(lambda: c.evaluate_operator({"name": "no-such-operator"}, [[0.5, 0.5]], op="union"),
                             422, "unknown_name", "operator.name")

    def test_parts_create_get_put_list_delete_and_their_errors(self):
        parts = self.client.parts
        bolt = parts.create(part("bolt"))
        self.assertEqual((bolt["kind"], bolt["name"], bolt["version"]), ("part", "bolt", 1))
        self.assertEqual(parts.get(bolt["id"])["document"]["params"]["a1"], 1)
        second = parts.put(bolt["id"], part("bolt", 2), if_version=1)
        self.assertEqual(second["version"], 2)
        self.assertEqual(parts.get(bolt["id"], version=1)["document"]["params"]["a1"], 1)
        stale = self.assertFsdbError(lambda: parts.put(bolt["id"], part("bolt", 3), if_version=1), 412,
                                     "precondition_failed", "If-Match")
        self.assertIn('"2"', stale.message)
        self.assertFsdbError(lambda: parts.create(part("bolt")), 409, "conflict", "name")
        self.assertFsdbError(lambda: parts.create(part("bad", -1)), 422, "invalid_parameter", "params.a1")
        self.assertEqual([p["name"] for p in parts.list(name="bolt")], ["bolt"])
        for i in range(5):
            parts.create(part(f"page-{i}"))
        names = [p["name"] for p in parts.list(page_size=2)]  # three pages and more
        self.assertEqual([n for n in names if n.startswith("page-")], [f"page-{i}" for i in range(5)])
        self.assertEqual(parts.delete(bolt["id"], if_version=2), [bolt["id"]])
        self.assertFsdbError(lambda: parts.get(bolt["id"]), 404, "not_found")

    def test_shapes_references_in_use_and_cascade(self):
        c = self.client
        a = c.parts.create(part("leg", 0.5))
        b = c.parts.create(part("top", 2))
        table = c.shapes.create({"name": "table", "tree": {"op": "union", "children": [{"part": "leg"}, {"part": "top"}]}})
        self.assertEqual(c.shapes.get(table["id"])["document"]["tree"]["op"], "union")
        self.assertFsdbError(lambda: c.parts.delete(a["id"]), 409, "in_use")
        self.assertFsdbError(lambda: c.shapes.create({"name": "x", "tree": {"part": "nowhere"}}), 422, "unknown_reference")
        self.assertEqual(sorted(c.parts.delete(a["id"], cascade=True)), sorted([a["id"], table["id"]]))
        c.parts.delete(b["id"])

    def test_bulk_import_numbers_lines_over_every_batch(self):
        docs = [part(f"bulk-{i}") for i in range(5)]
        docs[3] = part("bulk-bad", -2)
        report = self.client.bulk_import(docs, batch=2)
        self.assertEqual((report["imported"], report["failed"], len(report["ids"])), (4, 1, 4))
        self.assertEqual(report["errors"][0]["line"], 4)
        self.assertEqual(report["errors"][0]["error"]["path"], "params.a1")
        self.assertFalse(report["errors_truncated"])
        again = self.client.parts.bulk([part("bulk-0", 7)], mode="upsert")
        self.assertEqual(again["imported"], 1)
        self.assertEqual(self.client.parts.get(again["ids"][0])["version"], 2)
        self.assertFsdbError(lambda: self.client.parts.bulk([part("z")], mode="merge"), 422, "invalid_parameter", "mode")

    def test_evaluation_meshes_membership_and_pictures(self):
        c = self.client
        ball = c.parts.create(part("ball", 1, a2=1, a3=1))
        pair = c.shapes.create({"name": "pair", "tree": {"op": "union", "children": [
            {"part": "ball"},
            {"part": {"params": {"a1": 1, "a2": 1, "a3": 1}}, "transform": {"translate": [1.5, 0, 0]}}]}})
        inline = c.evaluate({"kind": "part", **part("inline")}, resolution=16, alphas=(0, 1))
        self.assertEqual([level["alpha"] for level in inline["alphas"]], [0, 1])
        stored = c.shapes.evaluate(pair["id"], resolution=16, alphas=(0.5,))
        self.assertIn("cached", stored)
        self.assertIn(b"\nf ", c.mesh(pair["id"], resolution=16))
        self.assertGreater(len(c.shapes.mesh(pair["id"], format="stl", resolution=16)), 84)
        self.assertEqual(c.parts.mesh(ball["id"], format="glb", resolution=16)[:4], b"glTF")
        self.assertEqual(c.membership(pair["id"], 0, 0, 0)["upper"], 1)
        self.assertEqual(c.parts.membership(ball["id"], 5, 5, 5)["upper"], 0)
        for picture in (c.parts.thumbnail(ball["id"], size=32), c.shapes.thumbnail(pair["id"], alpha=0.2, size=32)):
            self.assertEqual(picture[:8], b"\x89PNG\r\n\x1a\n")
        self.assertGreater(len(c.shapes.grid_vdb(pair["id"], resolution=16)), 100)
        self.assertFsdbError(lambda: c.membership(pair["id"], 0, 0, "x"), 422, "invalid_parameter")
        self.assertFsdbError(lambda: c.evaluate({"kind": "part", **part("tiny")}, resolution=1), 422,
                             "invalid_document", "resolution")
        with self.assertRaises(TypeError):
            c.curves.membership(1, 0, 0, 0)

    def test_mesh_of_an_inline_document(self):
        c = self.client
        doc = {"kind": "part", **part("inline-mesh", 1, a3=2)}
        stored = c.parts.create(doc)
        glb = c.mesh_document(doc, alpha=0.25, format="glb", resolution=16)
        self.assertEqual(glb[:4], b"glTF")
        self.assertEqual(glb, c.parts.mesh(stored["id"], alpha=0.25, format="glb", resolution=16))
        self.assertIn(b"\nf ", c.mesh_document(doc, bound="lower", resolution=12))
        self.assertFsdbError(lambda: c.mesh_document(doc, format="ply"), 422, "invalid_parameter", "format")

    def test_part_params_resolve_words(self):
        c = self.client
        worded = c.parts.create({"name": "worded", "text": "a slightly bent cylinder"})
        values = c.parts.params(worded["id"])
        self.assertEqual(values["version"], 1)
        self.assertIsInstance(values["params"]["kv"], dict)
        self.assertEqual(len(values["transform"]["translate"]), 3)
        self.assertEqual(c.parts.params(worded["id"], version=1)["params"], values["params"])
        self.assertFsdbError(lambda: c.parts.params(worded["id"], version=9), 404, "not_found")
        with self.assertRaises(TypeError):
            c.shapes.params(1)

    def test_family_members(self):
        c = self.client
        fuzzy = c.parts.create({"name": "family", "params": {"a1": {"tri": [0.8, 1, 1.2]}, "kv": {"tri": [0, 0.2, 0.4]}}})
        members = c.parts.members(fuzzy["id"], count=4)["members"]
        self.assertEqual(len(members), 4)
        self.assertEqual(members[0]["membership"], 1)
        degrees = [m["membership"] for m in members]
        self.assertEqual(degrees, sorted(degrees, reverse=True))
        self.assertLess(degrees[-1], 1)
        pair = c.shapes.create({"name": "family pair", "tree": {"op": "union", "children": [
            {"part": "family"}, {"part": {"params": {"a1": 1}}, "transform": {"translate": [2, 0, 0]}}]}})
        self.assertEqual(len(c.shapes.members(pair["id"], count=3)["members"]), 3)
        self.assertFsdbError(lambda: c.parts.members(fuzzy["id"], count=0), 422, "invalid_parameter", "count")
        with self.assertRaises(TypeError):
            c.curves.members(1)

    def test_searches(self):
        c = self.client
        c.parts.create(part("long-rod", 4, a2=0.3, a3=0.3))
        words = c.query("find a long part")
        self.assertEqual(words["search"], "linguistic")
        self.assertIn("long-rod", [r["name"] for r in words["results"]])
        self.assertIn("long-rod", [r["name"] for r in c.query_linguistic("find a long part", kind="part")["results"]])
        c.parts.create({"name": "box", "params": {"eps1": 0.1, "eps2": 0.1, "a1": 1, "a2": 1, "a3": 1}})
        c.parts.create({"name": "cyl", "params": {"eps1": 0.1, "eps2": 1, "a1": 0.5, "a2": 0.5, "a3": 2}})
        c.shapes.create({"name": "drilled", "tree": {"op": "difference", "children": [{"part": "box"}, {"part": "cyl"}]}})
        by_text = c.query_csg(text="a box minus a cylinder")
        self.assertEqual(by_text["results"][0]["name"], "drilled")
        tree = {"op": "difference", "children": [{"part": "box"}, {"part": "cyl"}]}
        self.assertEqual(c.query_csg(tree=tree, weights={"components": 1, "transforms": 0, "structure": 1})["results"][0]["name"], "drilled")
        self.assertEqual(c.query("a box minus a cylinder")["search"], "csg")
        self.assertFsdbError(lambda: c.query_csg(), 422, "invalid_document", "text")

    def test_curves_and_surfaces(self):
        c = self.client
        wave = c.curves.create({"name": "wave", "bezier": {"control_points": WAVE}})
        self.assertIn("<svg", c.curves.svg(wave["id"], alpha=0.5))
        fair = c.curves.create({"name": "fair", "fair": {"points": [[0, 0], [2, 1], [4, 0], [6, 1]], "samples": 8}})
        self.assertTrue(c.curves.candidates(fair["id"])["candidates"])
        # The designer's choice among the candidates: a new version, written only over version 1.
        chosen = c.curves.put(fair["id"], {**fair["document"], "chosen_candidate": 1}, if_version=1)
        self.assertEqual((chosen["version"], chosen["document"]["chosen_candidate"]), (2, 1))
        self.assertIn('id="candidate-1" stroke="#000000"', c.curves.svg(fair["id"]))
        self.assertFsdbError(lambda: c.curves.put(fair["id"], {**fair["document"], "chosen_candidate": 0}, if_version=1),
                             412, "precondition_failed", "If-Match")
        self.assertTrue(c.fair_curve([[0, 0], [2, 1], [4, 0]], samples=8)["candidates"])
        saddle = c.surfaces.create({"name": "saddle", "bezier": {"control_grid": SADDLE}})
        self.assertIn(b"\nf ", c.surfaces.mesh(saddle["id"], alpha=0.5))
        self.assertEqual(len(c.bezier_curve_evaluate(WAVE, [0, 0.5, 1], alpha=0.5)["points"]), 3)
        self.assertEqual(c.bezier_curve_elevate([[0, 0], [1, 1], [2, 0]], times=2)["degree"], 4)
        self.assertEqual(len(c.bezier_defuzzify("centroid", control_points=WAVE)["control_points"]), 4)
        self.assertEqual(len(c.bezier_surface_evaluate(SADDLE, [[0.5, 0.5]])["points"]), 1)
        self.assertEqual(c.bezier_surface_elevate(SADDLE, times_u=1, times_v=0)["degree"], [3, 2])
        self.assertIn("control_points", c.bezier_surface_iso(SADDLE, u=0.5))
        self.assertFsdbError(lambda: c.bezier_surface_iso(SADDLE), 422, "invalid_document", "u")
        self.assertFsdbError(lambda: c.curves.create({"name": "bad", "bezier": {"control_points": "none"}}), 422,
                             "invalid_document", "bezier.control_points")
        with self.assertRaises(TypeError):
            c.surfaces.svg(saddle["id"])


class ConnectionTest(unittest.TestCase):
    def test_an_unreachable_server_is_an_fsdb_error(self):
        with self.assertRaises(fsdb.FsdbError) as caught:
            fsdb.Client("http://127.0.0.1:9", timeout=5).health()
        self.assertEqual((caught.exception.status, caught.exception.code), (0, "unreachable"))

    def test_a_token_server_refuses_writes_without_the_token(self):
        server = Server("--token", "s3cret")
        try:
            anonymous = fsdb.Client(server.url)
            self.assertEqual(anonymous.health()["status"], "ok")  # reads need no token
            with self.assertRaises(fsdb.FsdbError) as caught:
                anonymous.parts.create(part("p"))
            self.assertEqual((caught.exception.status, caught.exception.code), (401, "unauthorized"))
            self.assertEqual(fsdb.Client(server.url, token="s3cret").parts.create(part("p"))["name"], "p")
        finally:
            server.stop()


if __name__ == "__main__":
    unittest.main()
