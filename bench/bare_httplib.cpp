// The baseline of bench/bench_get_part.sh: a bare cpp-httplib server that answers
// GET /KINDs/{id} with a fixed JSON body (the body fsdb returns for a stored part or shape, read
// from a file), with the same thread pool size fsdb uses, so the difference is fsdb's own work
// (routing, SQLite read, JSON build and dump, logging).
// Usage: bare_httplib BODY.json [THREADS] [nodelay|delay] [KIND]   (KIND: part, the default, or
// shape) prints "listening on http://127.0.0.1:PORT"
// "nodelay" sets TCP_NODELAY on accepted sockets (httplib writes headers and body separately;
// without it Nagle's algorithm and the client's delayed ACK add ~40 ms to keep-alive requests).
#include <httplib.h>
#include <netinet/tcp.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: bare_httplib BODY.json [THREADS]\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::stringstream text;
  text << in.rdbuf();
  const std::string body = text.str();
  const size_t threads = argc > 2 ? static_cast<size_t>(std::stoul(argv[2])) : 2;

  const bool nodelay = argc > 3 && std::string(argv[3]) == "nodelay";
  httplib::Server server;
  server.set_socket_options([nodelay](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
    if (nodelay) setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof(yes));
  });
  server.new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
  const std::string kind = argc > 4 ? argv[4] : "part";
  server.Get("/" + kind + R"(s/(\d+))",
             [&body](const httplib::Request&, httplib::Response& res) { res.set_content(body, "application/json"); });
  const int port = server.bind_to_any_port("127.0.0.1");
  if (port < 0) return 1;
  std::cout << "listening on http://127.0.0.1:" << port << std::endl;
  server.listen_after_bind();
  return 0;
}
