// What a browser needs of GET answers (server/http/response_encoding.h and its use by
// server/http/http_server.cpp): weak ETags and 304 on If-None-Match, gzip of binary exports,
// and CORS only when `--cors ORIGIN` asks for it.
#include "server/http/response_encoding.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include "server/http/http_server.h"
#include "tests/server/server_process.h"

using fsdb::test::ServerProcess;
using nlohmann::json;

namespace fsdb {
namespace {

std::string gunzip(const std::string& bytes) {
  z_stream z{};
  EXPECT_EQ(inflateInit2(&z, 15 + 16), Z_OK);
  std::string out;
  char buf[1 << 15];
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  int rc = Z_OK;
  while (rc == Z_OK) {
    z.next_out = reinterpret_cast<Bytef*>(buf);
    z.avail_out = sizeof buf;
    rc = inflate(&z, Z_NO_FLUSH);
    out.append(buf, sizeof buf - z.avail_out);
  }
  inflateEnd(&z);
  EXPECT_EQ(rc, Z_STREAM_END);
  return out;
}

TEST(ResponseEncoding, EntityTagsAndIfNoneMatch) {
  const std::string tag = entityTag("{\"a\":1}");
  EXPECT_EQ(tag.size(), std::string("W/\"0123456789abcdef\"").size());
  EXPECT_EQ(tag, entityTag("{\"a\":1}"));
  EXPECT_NE(tag, entityTag("{\"a\":2}"));
  EXPECT_TRUE(ifNoneMatchHits(tag, tag));
  EXPECT_TRUE(ifNoneMatchHits(tag.substr(2), tag));  // strong form of the same tag: weak comparison
  EXPECT_TRUE(ifNoneMatchHits("\"x\", " + tag + " ,\"y\"", tag));
  EXPECT_TRUE(ifNoneMatchHits("*", tag));
  EXPECT_FALSE(ifNoneMatchHits("\"x\"", tag));
  EXPECT_FALSE(ifNoneMatchHits("", tag));
}

TEST(ResponseEncoding, GzipAndWhatIsCompressedHere) {
  std::string text;
  for (int i = 0; i < 10000; ++i) text += "v 1.0 2.0 " + std::to_string(i) + "\n";
  const std::string z = gzipBody(text);
  EXPECT_LT(z.size(), text.size() / 3);
  EXPECT_EQ(gunzip(z), text);
  EXPECT_EQ(gunzip(gzipBody("")), "");
  EXPECT_TRUE(acceptsGzip("gzip"));
  EXPECT_TRUE(acceptsGzip("br, GZIP;q=0.5, deflate"));
  EXPECT_TRUE(acceptsGzip("*"));
  EXPECT_FALSE(acceptsGzip("gzip;q=0"));
  EXPECT_FALSE(acceptsGzip("br, deflate"));
  EXPECT_FALSE(acceptsGzip(""));
  EXPECT_TRUE(compressedHere("model/obj"));
  EXPECT_TRUE(compressedHere("model/gltf-binary"));
  EXPECT_TRUE(compressedHere("application/octet-stream"));
  EXPECT_FALSE(compressedHere("application/json"));
  EXPECT_FALSE(compressedHere("image/png"));
}

// A stored name may hold any character; the header must stay one well-formed parameter list.
TEST(ResponseEncoding, ContentDispositionSanitisesTheNameAndCarriesItExactly) {
  EXPECT_EQ(contentDisposition("attachment", "knob-upper-0.5.obj"),
            "attachment; filename=\"knob-upper-0.5.obj\"; filename*=UTF-8''knob-upper-0.5.obj");
  EXPECT_EQ(contentDisposition("inline", "a\"b\\c;d.png"),
            "inline; filename=\"a_b_c_d.png\"; filename*=UTF-8''a%22b%5Cc%3Bd.png");
  // UTF-8 bytes: replaced in the quoted form, percent-encoded in the RFC 5987 form.
  EXPECT_EQ(contentDisposition("attachment", "w\xC3\xBCrfel 1.glb"),
            "attachment; filename=\"w__rfel 1.glb\"; filename*=UTF-8''w%C3%BCrfel%201.glb");
  EXPECT_EQ(contentDisposition("attachment", std::string("a\r\nX: y", 7)),
            "attachment; filename=\"a__X_ y\"; filename*=UTF-8''a%0D%0AX%3A%20y");
}

TEST(ResponseEncoding, CorsOrigins) {
  EXPECT_TRUE(validCorsOrigin("*"));
  EXPECT_TRUE(validCorsOrigin("http://localhost:5173"));
  EXPECT_TRUE(validCorsOrigin("https://studio.example.com"));
  EXPECT_FALSE(validCorsOrigin("https://studio.example.com/app"));
  EXPECT_FALSE(validCorsOrigin("localhost:5173"));
  EXPECT_FALSE(validCorsOrigin(""));
}

// A stored shape of two spheres side by side (inline parts).
json twoKnobs() {
  return {{"name", "knobs"},
          {"tree",
           {{"op", "union"},
            {"children",
             {{{"part", {{"params", {{"a1", 1}}}}}},
              {{"part", {{"params", {{"a1", 1}}}}}, {"transform", {{"translate", {1.5, 0, 0}}}}}}}}}};
}

httplib::Result rawGet(const ServerProcess& server, const std::string& path, httplib::Headers headers) {
  httplib::Client c = server.client();
  c.set_decompress(false);
  return c.Get(path.c_str(), headers);
}

TEST(ResponseEncodingApi, ObjectsAndMeshesHaveETagsAnd304) {
  ServerProcess server;
  auto created = server.post("/parts", json{{"name", "knob"}, {"params", {{"a1", 1}}}});
  ASSERT_EQ(created.status, 201) << created.body;
  const std::string id = std::to_string(created.json["id"].get<int64_t>());
  auto shape = server.post("/shapes", twoKnobs());
  ASSERT_EQ(shape.status, 201) << shape.body;
  const std::string mesh = "/shapes/" + std::to_string(shape.json["id"].get<int64_t>()) + "/mesh?alpha=0.5&resolution=16";
  for (const std::string& path : {"/parts/" + id, mesh, std::string("/parts")}) {
    auto first = rawGet(server, path, {{"Accept-Encoding", "identity"}});
    ASSERT_TRUE(first);
    ASSERT_EQ(first->status, 200) << path << first->body;
    const std::string tag = first->get_header_value("ETag");
    // A stored object's tag is its version, strong (If-Match compares it); others are weak body hashes.
    if (path == "/parts/" + id) EXPECT_EQ(tag, "\"1\"");
    else ASSERT_EQ(tag.rfind("W/\"", 0), 0u) << path;
    auto again = rawGet(server, path, {{"If-None-Match", tag}});
    EXPECT_EQ(again->status, 304) << path;
    EXPECT_TRUE(again->body.empty()) << path;
    EXPECT_EQ(again->get_header_value("ETag"), tag) << path;
    auto other = rawGet(server, path, {{"If-None-Match", "W/\"0000000000000000\""}});
    EXPECT_EQ(other->status, 200) << path;
    EXPECT_EQ(other->body, first->body) << path;
  }
  // A new version has a new tag: the old one no longer gives 304.
  auto before = rawGet(server, "/parts/" + id, {});
  ASSERT_EQ(server.put("/parts/" + id, json{{"name", "knob"}, {"params", {{"a1", 2}}}}).status, 200);
  auto after = rawGet(server, "/parts/" + id, {{"If-None-Match", before->get_header_value("ETag")}});
  EXPECT_EQ(after->status, 200);
  EXPECT_NE(after->get_header_value("ETag"), before->get_header_value("ETag"));
  // Errors carry no tag.
  auto missing = rawGet(server, "/parts/999999", {});
  EXPECT_EQ(missing->status, 404);
  EXPECT_EQ(missing->get_header_value("ETag"), "");
}

// A name with a quote ended the quoted filename early: `filename="say "hi"-upper-...`.
TEST(ResponseEncodingApi, DownloadsOfANameWithAQuoteHaveAWellFormedFilename) {
  ServerProcess server;
  auto created = server.post("/parts", json{{"name", "say \"hi\"; ok"}, {"params", {{"a1", 1}}}});
  ASSERT_EQ(created.status, 201) << created.body;
  const std::string id = std::to_string(created.json["id"].get<int64_t>());
  // Raw bytes: httplib's client decodes %XX in header values.
  const std::string answer =
      server.exchange("GET /parts/" + id + "/mesh?alpha=0.5&resolution=16&format=stl HTTP/1.1\r\nHost: t\r\n\r\n", 60000);
  ASSERT_EQ(answer.rfind("HTTP/1.1 200", 0), 0u) << answer.substr(0, 400);
  EXPECT_NE(answer.find("\r\nContent-Disposition: attachment; filename=\"say _hi__ ok-upper-0.500000.stl\"; "
                        "filename*=UTF-8''say%20%22hi%22%3B%20ok-upper-0.500000.stl\r\n"),
            std::string::npos)
      << answer.substr(0, 400);
}

TEST(ResponseEncodingApi, MeshesAndJsonAreGzippedWhenAccepted) {
  ServerProcess server;
  auto shape = server.post("/shapes", twoKnobs());
  ASSERT_EQ(shape.status, 201) << shape.body;
  const std::string mesh = "/shapes/" + std::to_string(shape.json["id"].get<int64_t>()) + "/mesh?alpha=0.5&resolution=24";
  auto plain = rawGet(server, mesh, {{"Accept-Encoding", "identity"}});
  ASSERT_EQ(plain->status, 200) << plain->body;
  EXPECT_EQ(plain->get_header_value("Content-Encoding"), "");
  EXPECT_EQ(plain->get_header_value("Vary"), "Accept-Encoding");
  auto zipped = rawGet(server, mesh, {{"Accept-Encoding", "gzip"}});
  ASSERT_EQ(zipped->status, 200);
  EXPECT_EQ(zipped->get_header_value("Content-Encoding"), "gzip");
  EXPECT_LT(zipped->body.size(), plain->body.size() / 2);
  EXPECT_EQ(gunzip(zipped->body), plain->body);
  EXPECT_EQ(zipped->get_header_value("ETag"), plain->get_header_value("ETag"));  // one weak tag, both codings
  auto json = rawGet(server, "/openapi.json", {{"Accept-Encoding", "gzip"}});
  EXPECT_EQ(json->get_header_value("Content-Encoding"), "gzip");
  EXPECT_EQ(json::parse(gunzip(json->body))["openapi"], "3.0.3");
}

TEST(ResponseEncodingApi, CorsOnlyWhenAsked) {
  {
    ServerProcess server;
    auto r = rawGet(server, "/health", {{"Origin", "http://elsewhere.test"}});
    EXPECT_EQ(r->get_header_value("Access-Control-Allow-Origin"), "");
    httplib::Client c = server.client();
    auto preflight = c.Options("/parts");
    ASSERT_TRUE(preflight);
    EXPECT_NE(preflight->status, 204);
    EXPECT_EQ(preflight->get_header_value("Access-Control-Allow-Methods"), "");
  }
  ServerProcess server({"--cors", "http://studio.test:5173"});
  auto r = rawGet(server, "/health", {{"Origin", "http://studio.test:5173"}});
  EXPECT_EQ(r->get_header_value("Access-Control-Allow-Origin"), "http://studio.test:5173");
  EXPECT_NE(r->get_header_value("Access-Control-Expose-Headers").find("ETag"), std::string::npos);
  auto error = rawGet(server, "/parts/999999", {});
  EXPECT_EQ(error->status, 404);
  EXPECT_EQ(error->get_header_value("Access-Control-Allow-Origin"), "http://studio.test:5173");
  httplib::Client c = server.client();
  auto preflight = c.Options("/parts/7");
  ASSERT_TRUE(preflight);
  EXPECT_EQ(preflight->status, 204);
  EXPECT_NE(preflight->get_header_value("Access-Control-Allow-Methods").find("PUT"), std::string::npos);
  EXPECT_NE(preflight->get_header_value("Access-Control-Allow-Headers").find("If-None-Match"), std::string::npos);
  // A bad origin is refused at start with a message naming the form.
  const auto bad = fsdb::test::runFsdb({"serve", "--port", "0", "--cors", "studio.test/app"}, true);
  EXPECT_NE(bad.exitCode, 0);
  EXPECT_NE(bad.out.find("--cors takes an origin"), std::string::npos) << bad.out;
}

}  // namespace
}  // namespace fsdb

namespace fsdb {
namespace {

// The studio page's files (served from the build's web folder): scripts gzipped, a weak ETag of
// the file checked before any compression, 304 on a match, nothing outside the folder.
TEST(ResponseEncodingApi, StudioFilesAreTaggedAndScriptsGzipped) {
  ServerProcess server;
  auto page = rawGet(server, "/", {});
  ASSERT_EQ(page->status, 200) << page->body.substr(0, 200);
  EXPECT_NE(page->body.find("fsdb studio"), std::string::npos);
  auto script = rawGet(server, "/studio.js", {{"Accept-Encoding", "gzip"}});
  ASSERT_EQ(script->status, 200);
  EXPECT_EQ(script->get_header_value("Content-Type"), "application/x-javascript");
  EXPECT_EQ(script->get_header_value("Content-Encoding"), "gzip");
  const std::string plain = rawGet(server, "/studio.js", {{"Accept-Encoding", "identity"}})->body;
  EXPECT_EQ(gunzip(script->body), plain);
  const std::string tag = script->get_header_value("ETag");
  EXPECT_EQ(tag, entityTag(plain));  // the file's own tag, whatever the encoding
  auto again = rawGet(server, "/studio.js", {{"If-None-Match", tag}, {"Accept-Encoding", "gzip"}});
  EXPECT_EQ(again->status, 304);
  EXPECT_TRUE(again->body.empty());
  EXPECT_EQ(rawGet(server, "/vendor/../../CMakeCache.txt", {})->status, 404);
  EXPECT_EQ(rawGet(server, "/vendor/nothing.js", {})->status, 404);
  // The page's modules, under /modules/.
  auto module = rawGet(server, "/modules/part_editor.js", {{"Accept-Encoding", "gzip"}});
  ASSERT_EQ(module->status, 200);
  EXPECT_EQ(module->get_header_value("Content-Type"), "application/x-javascript");
  EXPECT_EQ(rawGet(server, "/modules/nothing.js", {})->status, 404);
  EXPECT_EQ(rawGet(server, "/modules/../../CMakeCache.txt", {})->status, 404);
}

}  // namespace
}  // namespace fsdb
