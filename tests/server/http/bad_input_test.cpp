// Bad requests against the real `fsdb serve --db FILE`: each gets a 4xx with the JSON error body
// {"error":{"code","message","path"}}, and the server keeps serving (GET /health is 200 after
// every one). Also the bearer token for writes.
#include <csignal>
#include <gtest/gtest.h>

#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using fsdb::test::TempDir;
using nlohmann::json;

namespace {

// Checks the status, the error body and the code (unless ""); `path` is checked when not null, and a
// message mentioning `mention` when that is not empty. Then /health must still answer.
void expectError(const ServerProcess& server, const ServerProcess::Reply& r, int status, const std::string& code,
                 const char* path = nullptr, const std::string& mention = "") {
  EXPECT_EQ(r.status, status) << r.body;
  ASSERT_TRUE(r.json.is_object() && r.json.contains("error")) << r.body;
  const json& e = r.json["error"];
  ASSERT_TRUE(e.contains("code") && e.contains("message") && e.contains("path")) << r.body;
  if (!code.empty()) {
    EXPECT_EQ(e["code"], code) << r.body;
  }
  EXPECT_TRUE(e["path"].is_string()) << r.body;
  if (path) {
    EXPECT_EQ(e["path"], path) << r.body;
  }
  EXPECT_FALSE(e["message"].get<std::string>().empty()) << r.body;
  if (!mention.empty()) {
    EXPECT_NE(e["message"].get<std::string>().find(mention), std::string::npos) << r.body;
  }
  EXPECT_EQ(server.get("/health").status, 200) << "after " << r.body;
}

// A part document; params without "a1" get a1 = 1.
json part(const std::string& name, json params = json::object()) {
  if (params.is_object() && !params.contains("a1")) params["a1"] = 1;
  return {{"kind", "part"}, {"name", name}, {"params", std::move(params)}};
}

// A union of `children` and the stored part "good" (a Boolean node needs two children).
json unionOf(const std::string& name, json children) {
  children.push_back({{"part", "good"}});
  return {{"kind", "shape"}, {"name", name}, {"tree", {{"op", "union"}, {"children", std::move(children)}}}};
}

class BadInput : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir = new TempDir;
    server = new ServerProcess({"--db", dir->file("bad.sqlite"), "--max-body-bytes", "4000", "--max-json-depth", "16",
                                "--max-resolution", "64", "--max-nodes", "20"});
    ASSERT_EQ(server->post("/parts", part("good")).status, 201);
  }
  static void TearDownTestSuite() {
    delete server;
    delete dir;
  }
  static TempDir* dir;
  static ServerProcess* server;
};
TempDir* BadInput::dir = nullptr;
ServerProcess* BadInput::server = nullptr;

TEST_F(BadInput, MalformedJsonAndWrongTypes) {
  const ServerProcess& s = *server;
  expectError(s, s.post("/parts", std::string("{\"kind\":\"part\",")), 400, "malformed_json", "body");
  expectError(s, s.post("/parts", std::string("")), 400, "malformed_json", "body");
  expectError(s, s.post("/parts", std::string("[1,2,3]")), 422, "invalid_document", "");
  expectError(s, s.post("/parts", json{{"kind", "part"}, {"name", 42}, {"params", {{"a1", 1}}}}), 422,
              "invalid_document", "name");
  expectError(s, s.post("/parts", json{{"kind", "part"}, {"name", ""}, {"params", {{"a1", 1}}}}), 422,
              "invalid_document", "name");
  expectError(s, s.post("/parts", json{{"kind", "part"}, {"params", {{"a1", 1}}}}), 422, "invalid_document", "name");
  expectError(s, s.post("/parts", json{{"kind", "part"}, {"name", "p"}, {"params", {1, 2}}}), 422, "invalid_document",
              "params");
  expectError(s, s.post("/parts", part("p", {{"a1", "banana"}})), 422, "", "params.a1");
  expectError(s, s.post("/parts", part("p", {{"a1", true}})), 422, "invalid_document", "params.a1");
}

TEST_F(BadInput, InvalidFuzzyNumbersNamingTheirPath) {
  const ServerProcess& s = *server;
  expectError(s, s.post("/parts", part("p", {{"a1", {{"tri", {2, 1, 3}}}}})), 422, "invalid_document",
              "params.a1.tri[1]");
  expectError(s, s.post("/parts", part("p", {{"a1", {{"points", {{1, 0.5}, {2, 1.5}}}}}})), 422, "invalid_document",
              nullptr);
  expectError(s, s.post("/parts", part("p", {{"a1", {{"points", json::array()}}}})), 422, "invalid_document", nullptr);
  expectError(s, s.post("/parts", part("p", {{"a1", {{"trap", {1, 2, 3}}}}})), 422, "invalid_document", nullptr);
  expectError(s, s.post("/parts", part("p", {{"a1", "NaN"}})), 422, "", "params.a1");
  expectError(s, s.post("/parts", part("p", {{"a1", "inf"}})), 422, "", "params.a1");
  expectError(s, s.post("/parts", std::string(R"({"kind":"part","name":"p","params":{"a1":1e999}})")), 422,
              "invalid_document", "params.a1");
  expectError(s, s.post("/parts", std::string(R"({"kind":"part","name":"p","params":{"a1":{"tri":[1,2,1e999]}}})")),
              422, "invalid_document", "params.a1.tri[2]");
  expectError(s, s.post("/parts", std::string(R"({"kind":"part","name":"p","params":{"a1":1,"a2":-1e999}})")), 422,
              "invalid_document", "params.a2");
  expectError(s, s.post("/evaluate", std::string(R"({"shape":{"kind":"part","params":{"a1":1}},"alphas":[1e400]})")),
              422, "invalid_document", "alphas[0]");
}

TEST_F(BadInput, OutOfRangeParametersAndUnknownFields) {
  const ServerProcess& s = *server;
  expectError(s, s.post("/parts", part("p", {{"eps1", 5}})), 422, "", "params.eps1");
  expectError(s, s.post("/parts", part("p", {{"eps2", 0}})), 422, "", "params.eps2");
  expectError(s, s.post("/parts", part("p", {{"a1", -1}})), 422, "", "params.a1");
  expectError(s, s.post("/parts", part("p", {{"kx", 2}})), 422, "", "params.kx");
  expectError(s, s.post("/parts", part("p", {{"a1", 1}, {"a3", 1}, {"kv", 100}})), 422, "", "params.kv");
  expectError(s, s.post("/parts", part("p", {{"a1", 1}, {"wobble", 1}})), 422, "invalid_document", "params.wobble");
  // Valid parts too small or too large to grid: a 422 naming the shape, not a 500 or null volumes.
  for (double a1 : {1e-300, 1e-7, 1e300}) {
    json request = {{"shape", {{"kind", "part"}, {"params", {{"a1", a1}}}}}, {"resolution", 16}};
    expectError(s, s.post("/evaluate", request), 422, "domain_error", "shape");
  }
  json extra = part("p");
  extra["colour"] = "red";
  expectError(s, s.post("/parts", extra), 422, "invalid_document", "colour");
  expectError(s, s.post("/parts", json{{"kind", "part"}, {"name", "p"}, {"text", "a glorbly frobnicated zyx"}}), 422,
              "", nullptr);
}

TEST_F(BadInput, ReferencesCyclesConflictsAndKinds) {
  const ServerProcess& s = *server;
  expectError(s, s.post("/shapes", unionOf("u", {{{"part", "nope"}}})), 422, "unknown_reference",
              "tree.children[0].part");
  expectError(s, s.post("/shapes", unionOf("u", {{{"ref", 999999}}})), 422, "unknown_reference",
              "tree.children[0].ref");
  expectError(s, s.post("/shapes", json{{"kind", "shape"}, {"name", "c"}, {"csg", "c = good + nope"}}), 422,
              "unknown_reference", "csg");
  // x -> y, then PUT x -> y and y -> x would close a cycle.
  auto x = s.post("/shapes", unionOf("cx", {{{"part", "good"}}}));
  ASSERT_EQ(x.status, 201) << x.body;
  auto y = s.post("/shapes", unionOf("cy", {{{"ref", "cx"}}}));
  ASSERT_EQ(y.status, 201) << y.body;
  expectError(s, s.put("/shapes/" + std::to_string(x.json["id"].get<int64_t>()), unionOf("cx", {{{"ref", "cy"}}})), 422,
              "reference_cycle", nullptr);
  EXPECT_EQ(s.get("/shapes/" + std::to_string(x.json["id"].get<int64_t>())).json["version"], 1);
  expectError(s, s.put("/shapes/" + std::to_string(x.json["id"].get<int64_t>()), unionOf("cx", {{{"ref", "cx"}}})), 422,
              "reference_cycle", nullptr);
  expectError(s, s.post("/parts", part("good")), 409, "conflict", nullptr);
  // A name change on PUT is a conflict too.
  expectError(s,
              s.put("/shapes/" + std::to_string(y.json["id"].get<int64_t>()), unionOf("renamed", {{{"part", "good"}}})),
              409, "conflict", nullptr);
  expectError(s, s.post("/parts", unionOf("u2", {{{"part", "good"}}})), 422, "invalid_document", "kind");
  expectError(s, s.post("/shapes", part("p2")), 422, "invalid_document", "kind");
  expectError(s, s.put("/parts/" + std::to_string(x.json["id"].get<int64_t>()), part("cx")), 404, "not_found");
}

TEST_F(BadInput, Limits) {
  const ServerProcess& s = *server;
  json big = part("big");
  big["meta"] = {{"blob", std::string(5000, 'x')}};
  expectError(s, s.post("/parts", big), 413, "limit_exceeded", nullptr, "max_body_bytes");
  std::string deep = R"({"kind":"part","name":"deep","meta":)";
  for (int i = 0; i < 40; ++i) deep += "[";
  for (int i = 0; i < 40; ++i) deep += "]";
  deep += "}";
  expectError(s, s.post("/parts", deep), 413, "limit_exceeded", "body");
  expectError(s, s.post("/evaluate", json{{"shape", part("e")}, {"resolution", 100000}}), 413, "limit_exceeded",
              "resolution", "max_resolution");
  auto shape = s.post("/shapes", unionOf("small", {{{"part", "good"}}}));
  ASSERT_EQ(shape.status, 201);
  const std::string sid = std::to_string(shape.json["id"].get<int64_t>());
  expectError(s, s.post("/shapes/" + sid + "/evaluate", json{{"resolution", 65}}), 413, "limit_exceeded", "resolution",
              "max_resolution");
  expectError(s, s.get("/shapes/" + sid + "/mesh?resolution=9999"), 413, "limit_exceeded", "resolution",
              "max_resolution");
  json many = json::array();
  for (int i = 0; i < 25; ++i) many.push_back({{"part", "good"}});
  expectError(s, s.post("/shapes", unionOf("many", many)), 413, "limit_exceeded", nullptr, "max_nodes");
  // Parentheses in a csg formula nest at most 64 deep (100000 took the server down).
  expectError(s,
              s.post("/shapes", json{{"kind", "shape"},
                                     {"name", "deep"},
                                     {"csg", std::string(1500, '(') + "good" + std::string(1500, ')')}}),
              413, "limit_exceeded", "csg", "deeper than 64 levels");
  // The URI limit: 414 naming it (httplib's own answer said only "request failed"), and a URI
  // just under it is served.
  expectError(s, s.get("/parts?name=" + std::string(9000, 'a')), 414, "limit_exceeded", "uri", "8192 bytes");
  EXPECT_EQ(s.get("/parts?name=" + std::string(8000, 'a')).status, 200);
  // A header line over httplib's limit: 400 saying so, with the JSON error body.
  auto c = s.client();
  const auto r = c.Get("/health", httplib::Headers{{"X-Big", std::string(9000, 'b')}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_NE(r->body.find("\"code\":\"bad_request\""), std::string::npos) << r->body;
  EXPECT_NE(r->body.find("8192 bytes"), std::string::npos) << r->body;
}

TEST_F(BadInput, PathsAndQueryParameters) {
  const ServerProcess& s = *server;
  // GET requests whose path segment or query parameter is invalid: (target, the parameter named).
  const std::vector<std::pair<std::string, std::string>> invalid = {
      {"/parts/abc", "id"},
      {"/parts/-3", "id"},
      {"/parts/1.5", "id"},
      {"/shapes/0/membership?x=0&y=0&z=0", "id"},
      // Every {id} is parsed alike: no sign, no overflow to "not found".
      {"/shapes/+1/membership?x=0&y=0&z=0", "id"},
      {"/parts/+1", "id"},
      {"/shapes/1e3/grid.vdb", "id"},
      {"/parts?limit=0", "limit"},
      {"/parts?limit=100000", "limit"},
      {"/parts?after=x", "after"},
      {"/parts?name=good&version=abc", "version"},
      {"/parts/1?version=0", "version"}};
  for (const auto& [target, parameter] : invalid)
    expectError(s, s.get(target), 422, "invalid_parameter", parameter.c_str());
  expectError(s, s.post("/shapes/99999999999999999999/evaluate", std::string("")), 422, "invalid_parameter", "id");
  expectError(s, s.get("/parts/99999999"), 404, "not_found");
  expectError(s, s.del("/parts/1?cascade=maybe"), 422, "invalid_parameter", "cascade");
  expectError(s, s.post("/parts/bulk?mode=merge", std::string("")), 422, "invalid_parameter", "mode");
  auto shape = s.post("/shapes", unionOf("q", {{{"part", "good"}}}));
  ASSERT_EQ(shape.status, 201);
  const std::string sid = std::to_string(shape.json["id"].get<int64_t>());
  expectError(s, s.get("/shapes/" + sid + "/membership?x=0&y=0"), 422, "invalid_parameter", "z");
  expectError(s, s.get("/shapes/" + sid + "/membership?x=a&y=0&z=0"), 422, "invalid_parameter", "x");
  // An encoded NUL ends the number early for strtod; the rest of the text still counts.
  expectError(s, s.get("/shapes/" + sid + "/membership?x=0%00junk&y=0&z=0"), 422, "invalid_parameter", "x");
  // A 19-digit id is refused without overflowing (undefined behaviour UBSan found).
  expectError(s, s.get("/shapes/9999999999999999999/membership?x=0&y=0&z=0"), 422, "invalid_parameter", "id");
  expectError(s, s.get("/shapes/" + sid + "/mesh?format=ply"), 422, "invalid_parameter", "format");
  expectError(s, s.get("/shapes/" + sid + "/mesh?bound=middle"), 422, "invalid_parameter", "bound");
  expectError(s, s.get("/shapes/" + sid + "/mesh?alpha=2"), 422, "invalid_parameter", "alpha");
  expectError(s, s.post("/shapes/" + sid + "/evaluate", json{{"shape", part("x")}}), 422, "invalid_document", "shape");
}

TEST_F(BadInput, RoutesAndMethods) {
  const ServerProcess& s = *server;
  expectError(s, s.get("/partz"), 404, "not_found", "");
  expectError(s, s.get("/parts/1/2/3"), 404, "not_found", "");
  expectError(s, s.put("/parts", part("x")), 405, "method_not_allowed", "");
  expectError(s, s.del("/health"), 405, "method_not_allowed", "");
  expectError(s, s.get("/parts/bulk"), 422, "invalid_parameter", "id");  // GET /parts/{id} with id "bulk"
  // A folder of the studio page was a 500 (its read threw "Is a directory").
  expectError(s, s.get("/vendor/addons"), 404, "not_found", "");
  expectError(s, s.get("/vendor"), 404, "not_found", "");
  // Methods httplib refuses before routing (one it does not know; PATCH without a body) were
  // 400 "line longer than 8192 bytes"; they are 405 with the path's methods.
  for (const std::string& request : {std::string("PROPFIND /parts HTTP/1.1\r\nHost: t\r\n\r\n"),
                                     std::string("PATCH /parts/1 HTTP/1.1\r\nHost: t\r\n\r\n")}) {
    const std::string answer = s.exchange(request, 10000);
    EXPECT_EQ(answer.rfind("HTTP/1.1 405", 0), 0u) << request << answer;
    EXPECT_NE(answer.find("\"code\":\"method_not_allowed\""), std::string::npos) << answer;
    EXPECT_NE(answer.find(request[0] == 'P' && request[1] == 'R' ? "Allow: POST, GET" : "Allow: GET, PUT, DELETE"),
              std::string::npos)
        << answer;
  }
  const std::string patched = s.exchange(
      "PATCH /parts/1 HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\nContent-Length: 2\r\n\r\n{}", 10000);
  EXPECT_EQ(patched.rfind("HTTP/1.1 405", 0), 0u) << patched;
  EXPECT_EQ(s.exchange("PATCH /nowhere HTTP/1.1\r\nHost: t\r\n\r\n", 10000).rfind("HTTP/1.1 404", 0), 0u);
  // Unknown methods on no route stay errors that say what is wrong.
  EXPECT_EQ(s.exchange("PROPFIND /nowhere HTTP/1.1\r\nHost: t\r\n\r\n", 10000).rfind("HTTP/1.1 400", 0), 0u);
  EXPECT_EQ(s.get("/health").status, 200);
}

TEST_F(BadInput, BulkReportsBadLinesAndImportsTheGoodOnes) {
  const ServerProcess& s = *server;
  const std::string body = part("bulk-a").dump() + "\n" + "{not json\n" + "\n" + part("bulk-b", {{"a1", -1}}).dump() +
                           "\n" + part("good").dump() + "\n" + unionOf("bulk-s", {{{"part", "bulk-a"}}}).dump() + "\n" +
                           part("bulk-c").dump() + "\n" + R"({"kind":"part","name":"bulk-d","params":{"a1":1e999}})" +
                           "\n";
  auto r = s.post("/parts/bulk", body, "application/x-ndjson");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["imported"], 2);
  EXPECT_EQ(r.json["failed"], 5);
  ASSERT_EQ(r.json["errors"].size(), 5u) << r.body;
  const json& e = r.json["errors"];
  EXPECT_EQ(e[0]["line"], 2);
  EXPECT_EQ(e[0]["error"]["code"], "malformed_json");
  EXPECT_EQ(e[1]["line"], 4);
  EXPECT_EQ(e[1]["error"]["path"], "params.a1");
  EXPECT_EQ(e[2]["line"], 5);
  EXPECT_EQ(e[2]["error"]["code"], "conflict");
  EXPECT_EQ(e[3]["line"], 6);
  EXPECT_EQ(e[3]["error"]["code"], "invalid_document");
  EXPECT_EQ(e[4]["line"], 8);
  EXPECT_EQ(e[4]["error"]["path"], "params.a1");
  for (const auto& err : e) EXPECT_TRUE(err["error"].contains("message") && err["error"].contains("path")) << err;
  EXPECT_EQ(s.get("/parts?name=bulk-a").json["items"].size(), 1u);
  EXPECT_EQ(s.get("/parts?name=bulk-c").json["items"].size(), 1u);
  EXPECT_TRUE(s.get("/parts?name=bulk-b").json["items"].empty());
  expectError(s, s.post("/parts/bulk", std::string("[{\"kind\":")), 400, "malformed_json", nullptr);
  EXPECT_EQ(s.get("/health").status, 200);
}

TEST(BadInputToken, WritesNeedTheTokenReadsDoNot) {
  TempDir dir;
  ServerProcess server({"--db", dir.file("token.sqlite"), "--token", "s3cret"});
  expectError(server, server.post("/parts", part("t")), 401, "unauthorized");
  server.setToken("wrong");
  expectError(server, server.post("/parts", part("t")), 401, "unauthorized");
  expectError(server, server.post("/parts/bulk", part("t").dump()), 401, "unauthorized");
  expectError(server, server.del("/parts/1"), 401, "unauthorized");
  server.setToken("s3cret");
  auto created = server.post("/parts", part("t"));
  ASSERT_EQ(created.status, 201) << created.body;
  const std::string at = "/parts/" + std::to_string(created.json["id"].get<int64_t>());
  server.setToken("");
  EXPECT_EQ(server.get(at).status, 200);
  EXPECT_EQ(server.get("/parts").status, 200);
  expectError(server, server.put(at, part("t", {{"a1", 2}})), 401, "unauthorized");
  EXPECT_EQ(server.get(at).json["version"], 1);
  // Evaluating a stored shape only reads: no token needed.
  server.setToken("s3cret");
  auto shape = server.post("/shapes", json{{"kind", "shape"}, {"name", "ts"}, {"tree", {{"part", "t"}}}});
  ASSERT_EQ(shape.status, 201) << shape.body;
  server.setToken("");
  EXPECT_EQ(
      server.post("/shapes/" + std::to_string(shape.json["id"].get<int64_t>()) + "/evaluate", json{{"resolution", 16}})
          .status,
      200);
}

// The token is checked before the body is read: a client that asks first (Expect: 100-continue,
// as curl does for large bodies) gets the 401 without sending its 50 MB; before, the server
// answered 100 Continue and waited for the whole body. A wrong token of another length is refused
// like any other, and a small unauthenticated body leaves the connection usable.
TEST(BadInputToken, UnauthenticatedWritesAreRefusedBeforeTheirBody) {
  TempDir dir;
  ServerProcess server({"--db", dir.file("early.sqlite"), "--token", "s3cret", "--max-body-bytes", "100000000"});
  double ms = 0;
  const std::string answer = server.exchange(
      "POST /parts HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\nExpect: 100-continue\r\n"
      "Content-Length: 50000000\r\n\r\n",
      10000, &ms);
  EXPECT_EQ(answer.rfind("HTTP/1.1 401", 0), 0u) << answer;
  EXPECT_NE(answer.find("WWW-Authenticate: Bearer"), std::string::npos) << answer;
  EXPECT_LT(ms, 9000) << answer;
  // With the token the same request is asked to continue.
  const std::string allowed = server.exchange(
      "POST /parts HTTP/1.1\r\nHost: t\r\nAuthorization: Bearer s3cret\r\nContent-Type: application/json\r\n"
      "Expect: 100-continue\r\nContent-Length: 50000000\r\n\r\n",
      10000);
  EXPECT_EQ(allowed.rfind("HTTP/1.1 100", 0), 0u) << allowed;
  // Reads (GET, and POSTs that only read) need no token, asked first or not.
  const std::string query = R"({"text":"a sphere"})";
  EXPECT_EQ(server
                .exchange("POST /query HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\nExpect: 100-continue\r\n"
                          "Content-Length: " +
                              std::to_string(query.size()) + "\r\n\r\n",
                          10000)
                .rfind("HTTP/1.1 100", 0),
            0u);
  for (const char* wrong : {"Bearer s3cre", "Bearer s3cret!", "Bearer ", "bearer s3cret", "s3cret"}) {
    const std::string reply = server.exchange("DELETE /parts/1 HTTP/1.1\r\nHost: t\r\nAuthorization: " + std::string(wrong) +
                                                  "\r\n\r\n",
                                              10000);
    EXPECT_EQ(reply.rfind("HTTP/1.1 401", 0), 0u) << wrong << reply;
  }
  // Without Expect the body is read and dropped, and the connection serves the next request.
  httplib::Client c = server.client();
  auto refused = c.Post("/parts", std::string(200000, 'x'), "application/json");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, 401);
  auto health = c.Get("/health");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
}

// Bodies as curl sends them. `curl -d` labels a JSON body application/x-www-form-urlencoded;
// httplib, left to read it, parsed it as a form and answered 413 "larger than max_body_bytes"
// for anything over 8 KiB, whatever the limit. Chunked bodies are held to the limit too, and
// a refused body leaves the keep-alive connection usable.
TEST(BadInputBodies, FormLabelledJsonOver8KiBChunkedAndMultipartBodies) {
  // The client below keeps writing bodies the server has refused and closed: like curl, it must
  // see the error on the socket, not die of SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  TempDir dir;
  ServerProcess server({"--db", dir.file("bodies.sqlite"), "--max-body-bytes", "100000"});
  json big = part("form-labelled");
  big["meta"] = {{"notes", std::string(20000, 'n')}};
  auto r = server.post("/parts", big.dump(), "application/x-www-form-urlencoded");
  EXPECT_EQ(r.status, 201) << r.body;
  std::string lines;
  for (int i = 0; i < 200; ++i) lines += part("bulk-form-" + std::to_string(i)).dump() + "\n";
  ASSERT_GT(lines.size(), 8192u);
  r = server.post("/parts/bulk", lines, "application/x-www-form-urlencoded");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json["imported"], 200);
  EXPECT_EQ(server.get("/parts?name=bulk-form-199").json["items"].size(), 1u);

  // Over the limit with a Content-Length, and chunked (httplib checks only Content-Length).
  big["meta"]["notes"] = std::string(150000, 'n');
  expectError(server, server.post("/parts", big.dump()), 413, "limit_exceeded", "body", "max_body_bytes=100000");
  httplib::Client c = server.client();
  const std::string chunked = big.dump();
  auto res = c.Post(
      "/parts", chunked.size(),
      [&](size_t offset, size_t length, httplib::DataSink& sink) {
        sink.write(chunked.data() + offset, std::min<size_t>(length, 4096));
        return true;
      },
      "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 413) << res->body;
  res = c.Post(
      "/parts",
      [&](size_t offset, httplib::DataSink& sink) {
        if (offset < chunked.size())
          sink.write(chunked.data() + offset, std::min<size_t>(4096, chunked.size() - offset));
        else sink.done();
        return true;
      },
      "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 413) << res->body;
  EXPECT_NE(res->body.find("max_body_bytes=100000"), std::string::npos) << res->body;

  // Multipart (curl -F) is refused, and the same connection still serves the next request.
  httplib::Client keep = server.client();
  keep.set_keep_alive(true);
  httplib::MultipartFormDataItems items = {{"doc", part("multi").dump(), "doc.json", "application/json"}};
  res = keep.Post("/parts", items);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 415) << res->body;
  EXPECT_EQ(json::parse(res->body)["error"]["code"], "unsupported_media_type");
  res = keep.Post("/parts", part("after-multipart").dump(), "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 201) << res->body;
  EXPECT_EQ(server.get("/health").status, 200);
}

}  // namespace
