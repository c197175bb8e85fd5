"""The client covers every route of schema/openapi.json: a route added to the server without a
client method fails here."""
import inspect
import json
import unittest

import fsdb
from fsdb.client import Client, Collection
from server import REPO


class RoutesTest(unittest.TestCase):
    def test_every_route_of_the_openapi_document_has_a_method(self):
        document = json.loads((REPO / "schema" / "openapi.json").read_text())
        routes = {(method.upper(), path) for path, ops in document["paths"].items()
                  for method in ops if method in ("get", "post", "put", "delete")}
        self.assertEqual(sorted(routes - set(fsdb.ROUTES)), [], "routes without a client method")
        self.assertEqual(sorted(set(fsdb.ROUTES) - routes), [], "client methods for routes the server lacks")

    def test_every_named_method_exists_with_a_docstring(self):
        for route, name in fsdb.ROUTES.items():
            owner, method = name.split(".")
            function = getattr({"Client": Client, "Collection": Collection}[owner], method, None)
            self.assertIsNotNone(function, f"{name} for {route}")
            self.assertTrue(inspect.getdoc(function), f"{name} has no docstring")


if __name__ == "__main__":
    unittest.main()
