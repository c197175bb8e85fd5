"""fsdb.Client: every route of the server's OpenAPI document as a method (ROUTES maps them).

Requests go through urllib (one connection per request); bodies are JSON, answers JSON, bytes
(meshes, PNG, VDB) or text (SVG, OBJ) as the route gives them.
"""
from __future__ import annotations

import json
import sys
import urllib.error
import urllib.parse
import urllib.request
from typing import Any, Dict, Iterable, Iterator, List, Optional, Sequence, Tuple

Json = Dict[str, Any]


class FsdbError(Exception):
    """An error answer of the server: {"error": {"code", "message", "path"}} and its HTTP status.

    status 0 means the server could not be reached (code "unreachable")."""

    def __init__(self, status: int, code: str, message: str, path: str = ""):
        super().__init__(f"{status} {code}: {message}" + (f" (at {path})" if path else ""))
        self.status = status
        self.code = code
        self.message = message
        self.path = path


class _Http:
    def __init__(self, url: str, token: Optional[str], timeout: float):
        self.url = url.rstrip("/")
        self.token = token
        self.timeout = timeout

    def request(self, method: str, path: str, body: Any = None, query: Optional[Json] = None,
                headers: Optional[Dict[str, str]] = None, raw: Optional[bytes] = None,
                content_type: str = "application/json") -> Tuple[int, Dict[str, str], bytes]:
        url = self.url + path
        if query:
            params = {k: _query_value(v) for k, v in query.items() if v is not None}
            if params:
                url += "?" + urllib.parse.urlencode(params)
        data = raw
        if body is not None:
            data = json.dumps(body).encode("utf-8")
        elif data is None and method in ("POST", "PUT"):
            data = b""  # the server wants a body (Content-Length: 0) on every POST and PUT
        request = urllib.request.Request(url, data=data, method=method)
        if data is not None:
            request.add_header("Content-Type", content_type)
        if self.token:
            request.add_header("Authorization", "Bearer " + self.token)
        for name, value in (headers or {}).items():
            request.add_header(name, value)
        try:
            with urllib.request.urlopen(request, timeout=self.timeout) as answer:
                return answer.status, dict(answer.headers.items()), answer.read()
        except urllib.error.HTTPError as e:
            payload = e.read()
            try:
                error = json.loads(payload)["error"]
                raise FsdbError(e.code, error.get("code", ""), error.get("message", ""), error.get("path", "")) from None
            except (ValueError, KeyError, TypeError):
                raise FsdbError(e.code, "http_%d" % e.code, payload.decode("utf-8", "replace")) from None
        except urllib.error.URLError as e:
            raise FsdbError(0, "unreachable", f"cannot reach {self.url}: {e.reason}") from None

    def json(self, method: str, path: str, body: Any = None, query: Optional[Json] = None,
             headers: Optional[Dict[str, str]] = None) -> Any:
        return json.loads(self.request(method, path, body, query, headers)[2])


def _query_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def _etag(version: Optional[int]) -> Optional[Dict[str, str]]:
    return {"If-Match": '"%d"' % version} if version is not None else None


class Collection:
    """Stored objects of one kind: client.parts, .shapes, .curves, .surfaces.

    Objects come back as the server stores them: {"id", "kind", "name", "version",
    "latest_version", "created_at", "content_hash", "document"}."""

    def __init__(self, http: _Http, kind: str):
        self._http = http
        self.kind = kind
        self._base = "/" + kind + "s"

    def create(self, doc: Json) -> Json:
        """POST /K: stores a new object (409 conflict when the name is taken)."""
        return self._http.json("POST", self._base, doc)

    def get(self, id: int, version: Optional[int] = None) -> Json:
        """GET /K/{id}: the latest version, or `version`."""
        return self._http.json("GET", f"{self._base}/{id}", query={"version": version})

    def put(self, id: int, doc: Json, if_version: Optional[int] = None) -> Json:
        """PUT /K/{id}: a new version; with if_version, only while that is the latest (else 412)."""
        return self._http.json("PUT", f"{self._base}/{id}", doc, headers=_etag(if_version))

    def delete(self, id: int, cascade: bool = False, if_version: Optional[int] = None) -> List[int]:
        """DELETE /K/{id}: the ids deleted, the object first (cascade: everything reaching it too)."""
        answer = self._http.json("DELETE", f"{self._base}/{id}", query={"cascade": cascade or None},
                                 headers=_etag(if_version))
        return answer["deleted"]

    def list(self, name: Optional[str] = None, page_size: int = 100) -> Iterator[Json]:
        """GET /K, every page: an iterator over the objects (by id), or those named `name`."""
        after = None
        while True:
            page = self._http.json("GET", self._base, query={"name": name, "after": after, "limit": page_size})
            yield from page["items"]
            after = page["next_after"]
            if after is None:
                return

    def bulk(self, docs: Iterable[Json], mode: str = "create", batch: int = 500) -> Json:
        """POST /K/bulk with these documents as JSON Lines, in one request."""
        body = "".join(json.dumps(d) + "\n" for d in docs).encode("utf-8")
        return json.loads(self._http.request("POST", self._base + "/bulk", raw=body,
                                             query={"mode": mode, "batch": batch},
                                             content_type="application/x-ndjson")[2])

    # Kind-specific reads; each refuses the kinds the server has no such route for.
    def mesh(self, id: int, alpha: float = 0.5, bound: str = "upper", format: str = "obj",
             resolution: Optional[int] = None) -> bytes:
        """GET /K/{id}/mesh (parts, shapes, surfaces): OBJ or STL text, or GLB, as bytes."""
        self._only("part", "shape", "surface")
        return self._http.request("GET", f"{self._base}/{id}/mesh",
                                  query={"alpha": alpha, "bound": bound, "format": format,
                                         "resolution": resolution})[2]

    def membership(self, id: int, x: float, y: float, z: float) -> Json:
        """GET /K/{id}/membership (parts, shapes): the levels of one point."""
        self._only("part", "shape")
        return self._http.json("GET", f"{self._base}/{id}/membership", query={"x": x, "y": y, "z": z})

    def members(self, id: int, count: int = 9) -> Json:
        """GET /K/{id}/members (parts, shapes): the family's crisp members with their degrees."""
        self._only("part", "shape")
        return self._http.json("GET", f"{self._base}/{id}/members", query={"count": count})

    def params(self, id: int, version: Optional[int] = None) -> Json:
        """GET /parts/{id}/params: the part's fourteen fuzzy values, its words resolved."""
        self._only("part")
        return self._http.json("GET", f"{self._base}/{id}/params", query={"version": version})

    def thumbnail(self, id: int, alpha: float = 0.5, size: int = 128) -> bytes:
        """GET /K/{id}/thumbnail.png (parts, shapes): PNG bytes."""
        self._only("part", "shape")
        return self._http.request("GET", f"{self._base}/{id}/thumbnail.png", query={"alpha": alpha, "size": size})[2]

    def evaluate(self, id: int, resolution: int = 64, alphas: Sequence[float] = (0, 0.5, 1),
                 method: str = "envelope") -> Json:
        """POST /shapes/{id}/evaluate: fuzzy volumes of a stored shape (cached by content)."""
        self._only("shape")
        return self._http.json("POST", f"{self._base}/{id}/evaluate",
                               {"resolution": resolution, "alphas": list(alphas), "method": method})

    def grid_vdb(self, id: int, resolution: int = 64) -> bytes:
        """GET /shapes/{id}/grid.vdb: both grids as an OpenVDB file."""
        self._only("shape")
        return self._http.request("GET", f"{self._base}/{id}/grid.vdb", query={"resolution": resolution})[2]

    def svg(self, id: int, alpha: Optional[float] = None, samples: Optional[int] = None,
            candidate: Optional[int] = None) -> str:
        """GET /curves/{id}/svg: the curve drawn as SVG."""
        self._only("curve")
        return self._http.request("GET", f"{self._base}/{id}/svg",
                                  query={"alpha": alpha, "samples": samples, "candidate": candidate})[2].decode()

    def candidates(self, id: int) -> Json:
        """GET /curves/{id}/candidates: the candidates of a stored fair curve."""
        self._only("curve")
        return self._http.json("GET", f"{self._base}/{id}/candidates")

    def _only(self, *kinds: str) -> None:
        if self.kind not in kinds:
            raise TypeError(f"{self.kind}s have no such route (only {', '.join(k + 's' for k in kinds)})")


class Client:
    """One fsdb server. token: the bearer token of a server started with --token."""

    def __init__(self, url: str = "http://127.0.0.1:8080", token: Optional[str] = None, timeout: float = 600):
        self._http = _Http(url, token, timeout)
        self.parts = Collection(self._http, "part")
        self.shapes = Collection(self._http, "shape")
        self.curves = Collection(self._http, "curve")
        self.surfaces = Collection(self._http, "surface")

    # --- the service ---
    def health(self) -> Json:
        """GET /health: status, version, counts, schema version, backend."""
        return self._http.json("GET", "/health")

    def openapi(self) -> Json:
        """GET /openapi.json: the server's OpenAPI document."""
        return self._http.json("GET", "/openapi.json")

    def metrics(self) -> str:
        """GET /metrics: the server's counters and gauges in the Prometheus text format."""
        return self._http.request("GET", "/metrics")[2].decode("utf-8")

    def vocabulary(self) -> Json:
        """GET /vocabulary: the words the searches understand."""
        return self._http.json("GET", "/vocabulary")

    def operators(self) -> Json:
        """GET /operators: the fuzzy set operator catalogue."""
        return self._http.json("GET", "/operators")

    def evaluate_operator(self, operator: Json, points: Sequence[Any], op: Optional[str] = None) -> Json:
        """POST /operators/evaluate: one operator ({"name": ..., params}) at many points."""
        body: Json = {"operator": operator, "points": list(points)}
        if op is not None:
            body["op"] = op
        return self._http.json("POST", "/operators/evaluate", body)

    # --- bulk import ---
    def bulk_import(self, docs: Iterable[Json], kind: str = "part", batch: int = 1000, mode: str = "create") -> Json:
        """Imports documents of one kind, `batch` a request (and a transaction): {"imported",
        "failed", "ids", "errors", "errors_truncated"}, error lines numbered from 1 over all of
        `docs`; each request lists at most the server's --max-bulk-errors failed lines, and
        errors_truncated is true when some were left out. Shows a progress bar on a terminal
        (tqdm when installed)."""
        collection = getattr(self, kind + "s")
        docs = list(docs)
        report: Json = {"imported": 0, "failed": 0, "ids": [], "errors": [], "errors_truncated": False}
        bar = _progress(len(docs))
        for start in range(0, len(docs), batch):
            chunk = docs[start:start + batch]
            answer = collection.bulk(chunk, mode=mode, batch=batch)
            report["imported"] += answer["imported"]
            report["failed"] += answer["failed"]
            report["ids"] += answer["ids"]
            for e in answer["errors"]:
                report["errors"].append({"line": e["line"] + start, "error": e["error"]})
            report["errors_truncated"] = report["errors_truncated"] or answer.get("errors_truncated", False)
            bar(len(chunk))
        bar(0, done=True)
        return report

    # --- evaluation ---
    def evaluate(self, doc: Json, resolution: int = 64, alphas: Sequence[float] = (0, 0.5, 1),
                 method: str = "envelope") -> Json:
        """POST /evaluate: fuzzy volumes per level of an inline shape or part document."""
        return self._http.json("POST", "/evaluate",
                               {"shape": doc, "resolution": resolution, "alphas": list(alphas), "method": method})

    def mesh(self, shape_id: int, alpha: float = 0.5, bound: str = "upper", format: str = "obj",
             resolution: Optional[int] = None) -> bytes:
        """GET /shapes/{id}/mesh: the surface of lower(alpha) or upper(alpha)."""
        return self.shapes.mesh(shape_id, alpha, bound, format, resolution)

    def mesh_document(self, doc: Json, alpha: float = 0.5, bound: str = "upper", format: str = "obj",
                      resolution: Optional[int] = None) -> bytes:
        """POST /mesh: the mesh file of an inline shape or part document (as the stored form's)."""
        body = _without_none({"shape": doc, "alpha": alpha, "bound": bound, "format": format,
                              "resolution": resolution})
        return self._http.request("POST", "/mesh", body)[2]

    def membership(self, shape_id: int, x: float, y: float, z: float) -> Json:
        """GET /shapes/{id}/membership: the levels of the point (x, y, z)."""
        return self.shapes.membership(shape_id, x, y, z)

    # --- search ---
    def query(self, text: str, limit: int = 10, **members: Any) -> Json:
        """POST /query: the search the text calls for (answer["search"]: "linguistic" or "csg").

        Words neither grammar knows are read around: typos (no WordNet word) are corrected and
        listed in answer["routed"] (why "spelling"), other words are left out and listed in
        answer["ignored"] with their closest words; answer["read_text"] is what was searched. A text that no grammar
        reads even so is searched by the run of its words that reads (answer["run_discount"]
        multiplies its scores); names the text nearly holds come first (named: true)."""
        return self._http.json("POST", "/query", {"text": text, "limit": limit, **members})

    def query_linguistic(self, text: str, limit: int = 10, threshold: Optional[float] = None,
                         kind: Optional[str] = None) -> Json:
        """POST /query/linguistic: parts and shapes described by words, best first."""
        body: Json = {"text": text, "limit": limit}
        if threshold is not None:
            body["threshold"] = threshold
        if kind is not None:
            body["kind"] = kind
        return self._http.json("POST", "/query/linguistic", body)

    def query_csg(self, tree: Optional[Json] = None, text: Optional[str] = None,
                  weights: Optional[Json] = None, limit: int = 10) -> Json:
        """POST /query/csg: stored shapes whose CSG trees match a tree or a text (exactly one)."""
        body: Json = {"limit": limit}
        if tree is not None:
            body["tree"] = tree
        if text is not None:
            body["text"] = text
        if weights is not None:
            body["weights"] = weights
        return self._http.json("POST", "/query/csg", body)

    # --- curves and surfaces computed without storing ---
    def fair_curve(self, points: Sequence[Sequence[float]], **members: Any) -> Json:
        """POST /curves/fair: ranked candidate fair curves through plane points."""
        return self._http.json("POST", "/curves/fair", {"points": [list(p) for p in points], **members})

    def bezier_curve_evaluate(self, control_points: Sequence[Any], u: Sequence[float], alpha: float = 0,
                              weights: Optional[Sequence[Any]] = None) -> Json:
        """POST /curves/bezier/evaluate: points of a fuzzy Bezier curve at level alpha."""
        return self._http.json("POST", "/curves/bezier/evaluate",
                               _without_none({"control_points": list(control_points), "u": list(u),
                                              "alpha": alpha, "weights": weights}))

    def bezier_curve_elevate(self, control_points: Sequence[Any], times: int = 1,
                             weights: Optional[Sequence[Any]] = None) -> Json:
        """POST /curves/bezier/elevate: degree elevation of a fuzzy Bezier curve."""
        return self._http.json("POST", "/curves/bezier/elevate",
                               _without_none({"control_points": list(control_points), "times": times,
                                              "weights": weights}))

    def bezier_defuzzify(self, method: str, control_points: Optional[Sequence[Any]] = None,
                         control_grid: Optional[Sequence[Any]] = None, weights: Optional[Sequence[Any]] = None) -> Json:
        """POST /curves/bezier/defuzzify: crisp control points (or grid) from fuzzy ones."""
        return self._http.json("POST", "/curves/bezier/defuzzify",
                               _without_none({"method": method, "control_points": control_points,
                                              "control_grid": control_grid, "weights": weights}))

    def bezier_surface_evaluate(self, control_grid: Sequence[Any], uv: Sequence[Sequence[float]],
                                alpha: float = 0) -> Json:
        """POST /surfaces/bezier/evaluate: points of a fuzzy tensor-product Bezier surface."""
        return self._http.json("POST", "/surfaces/bezier/evaluate",
                               {"control_grid": control_grid, "uv": [list(p) for p in uv], "alpha": alpha})

    def bezier_surface_elevate(self, control_grid: Sequence[Any], times_u: int = 1, times_v: int = 1) -> Json:
        """POST /surfaces/bezier/elevate: degree elevation of a surface."""
        return self._http.json("POST", "/surfaces/bezier/elevate",
                               {"control_grid": control_grid, "times_u": times_u, "times_v": times_v})

    def bezier_surface_iso(self, control_grid: Sequence[Any], u: Optional[float] = None,
                           v: Optional[float] = None) -> Json:
        """POST /surfaces/bezier/iso: the iso-parametric curve at u or at v (exactly one)."""
        return self._http.json("POST", "/surfaces/bezier/iso", _without_none({"control_grid": control_grid, "u": u, "v": v}))


def _without_none(body: Json) -> Json:
    return {k: v for k, v in body.items() if v is not None}


def _progress(total: int):
    """A callable bar(n, done=False) advancing a progress bar on a terminal, else doing nothing."""
    if not sys.stderr.isatty():
        return lambda n, done=False: None
    try:
        from tqdm import tqdm  # type: ignore
        bar = tqdm(total=total, unit="doc")

        def advance(n: int, done: bool = False) -> None:
            bar.update(n)
            if done:
                bar.close()
        return advance
    except ImportError:
        state = {"done": 0}

        def advance(n: int, done: bool = False) -> None:
            state["done"] += n
            width = 30
            filled = width * state["done"] // max(1, total)
            sys.stderr.write("\r[%s%s] %d/%d" % ("#" * filled, " " * (width - filled), state["done"], total))
            if done:
                sys.stderr.write("\n")
            sys.stderr.flush()
        return advance


# Every route of schema/openapi.json and the method that calls it ("Collection.x" for each kind
# that has the route). tests/test_routes.py fails when the server gains a route missing here.
ROUTES: Dict[Tuple[str, str], str] = {
    ("GET", "/health"): "Client.health",
    ("GET", "/openapi.json"): "Client.openapi",
    ("GET", "/metrics"): "Client.metrics",
    ("GET", "/operators"): "Client.operators",
    ("POST", "/operators/evaluate"): "Client.evaluate_operator",
    ("GET", "/vocabulary"): "Client.vocabulary",
    ("POST", "/evaluate"): "Client.evaluate",
    ("POST", "/mesh"): "Client.mesh_document",
    ("POST", "/query"): "Client.query",
    ("POST", "/query/linguistic"): "Client.query_linguistic",
    ("POST", "/query/csg"): "Client.query_csg",
    ("POST", "/curves/fair"): "Client.fair_curve",
    ("POST", "/curves/bezier/evaluate"): "Client.bezier_curve_evaluate",
    ("POST", "/curves/bezier/elevate"): "Client.bezier_curve_elevate",
    ("POST", "/curves/bezier/defuzzify"): "Client.bezier_defuzzify",
    ("POST", "/surfaces/bezier/evaluate"): "Client.bezier_surface_evaluate",
    ("POST", "/surfaces/bezier/elevate"): "Client.bezier_surface_elevate",
    ("POST", "/surfaces/bezier/iso"): "Client.bezier_surface_iso",
    ("POST", "/shapes/{id}/evaluate"): "Collection.evaluate",
    ("GET", "/shapes/{id}/grid.vdb"): "Collection.grid_vdb",
    ("GET", "/curves/{id}/svg"): "Collection.svg",
    ("GET", "/curves/{id}/candidates"): "Collection.candidates",
    ("GET", "/parts/{id}/params"): "Collection.params",
}
for _kind in ("parts", "shapes", "curves", "surfaces"):
    ROUTES[("POST", f"/{_kind}")] = "Collection.create"
    ROUTES[("GET", f"/{_kind}")] = "Collection.list"
    ROUTES[("GET", f"/{_kind}/{{id}}")] = "Collection.get"
    ROUTES[("PUT", f"/{_kind}/{{id}}")] = "Collection.put"
    ROUTES[("DELETE", f"/{_kind}/{{id}}")] = "Collection.delete"
    ROUTES[("POST", f"/{_kind}/bulk")] = "Collection.bulk"
for _kind in ("parts", "shapes", "surfaces"):
    ROUTES[("GET", f"/{_kind}/{{id}}/mesh")] = "Collection.mesh"
for _kind in ("parts", "shapes"):
    ROUTES[("GET", f"/{_kind}/{{id}}/membership")] = "Collection.membership"
    ROUTES[("GET", f"/{_kind}/{{id}}/members")] = "Collection.members"
    ROUTES[("GET", f"/{_kind}/{{id}}/thumbnail.png")] = "Collection.thumbnail"
