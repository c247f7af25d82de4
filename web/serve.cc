// `icpbench serve DIR`: checks the store, registers the handlers, binds, and
// serves until SIGINT or SIGTERM (a thread waits for them and stops the
// server). A handler's HttpError becomes its 4xx with {"error": message}; a
// store that cannot be read during a request (a foreign file, an error) a 500.
#include "web/serve.h"

#include <netdb.h>
#include <pthread.h>
#include <signal.h>
#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "harness/environment_error.h"
#include "harness/results_store.h"
#include "web/api.h"

namespace icp::web {

namespace {

// An error's JSON, sent whole: cpp-httplib slices whatever answer it sends
// by the request's Range header (a 400 cut to its bytes 10-, a 416 in
// pieces), so the ranges are forgotten. The request is the server's own
// (made non-const), handed to handlers as const.
void SendError(const httplib::Request& req, httplib::Response& res, int status,
               const std::string& message) {
  const_cast<httplib::Request&>(req).ranges.clear();
  res.status = status;
  res.set_content(nlohmann::json({{"error", message}}).dump(-1, ' ', false,
                                                           nlohmann::json::error_handler_t::replace),
                  "application/json");
}

void CheckAsset(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw EnvironmentError("the page's asset '" + path + "' is missing (reinstall icpbench" +
                           (path.find("chart") != std::string::npos
                                ? "; Chart.js is Debian's libjs-chart.js: bash scripts/deps.sh"
                                : "") +
                           ")");
}

// A query the routes would misread, said before any route runs: their
// values are matched as text, so a NUL byte (the decoded value stops at it)
// or a key given twice (two filters ANDed into nothing) is refused.
std::string BadQuery(const httplib::Request& req) {
  const std::string& target = req.target;
  for (std::size_t at = target.find('%'); at != std::string::npos; at = target.find('%', at + 1))
    if (target.compare(at, 3, "%00") == 0) return "a NUL byte (%00) in the URL";
  // cpp-httplib splits on ';' too and keeps what follows a value's last '=':
  // limit=3;offset=1 read limit as 1. Such characters must be encoded.
  if (const std::size_t q = target.find('?'); q != std::string::npos) {
    std::size_t start = q + 1;
    while (start <= target.size()) {
      std::size_t end = target.find('&', start);
      if (end == std::string::npos) end = target.size();
      const std::string item = target.substr(start, end - start);
      if (item.find(';') != std::string::npos ||
          std::count(item.begin(), item.end(), '=') > 1)
        return "a raw ';' or a second '=' in the query item '" + item +
               "' (encode them: %3B, %3D)";
      start = end + 1;
    }
  }
  std::set<std::string> seen;
  for (const auto& [name, value] : req.params)
    if (!seen.insert(name).second)
      return "query parameter '" + name + "' given twice (list values with commas: a,b)";
  return "";
}

// The numeric addresses host resolves to, as getnameinfo writes them
// ("127.0.0.1", "::1"); empty when it does not resolve.
std::vector<std::string> NumericAddresses(const std::string& host) {
  addrinfo hints{};
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (getaddrinfo(host.c_str(), nullptr, &hints, &found) != 0) return {};
  std::vector<std::string> out;
  for (const addrinfo* a = found; a != nullptr; a = a->ai_next) {
    char text[NI_MAXHOST];
    if (getnameinfo(a->ai_addr, a->ai_addrlen, text, sizeof text, nullptr, 0, NI_NUMERICHOST) == 0)
      out.push_back(text);
  }
  freeaddrinfo(found);
  return out;
}

bool IsLoopback(const std::string& numeric) {
  return numeric.rfind("127.", 0) == 0 || numeric == "::1" || numeric.rfind("::ffff:127.", 0) == 0;
}

// The Host headers a server bound to a loopback host answers: the printed
// authority, localhost and every numeric spelling of the bound addresses
// (so 127.1, 2130706433 and 0:0:0:0:0:0:0:1 are checked as what they are);
// empty (any Host) for a host that is not loopback only.
std::set<std::string> LoopbackHostNames(const std::string& host, const std::string& authority,
                                        int port) {
  const std::vector<std::string> addresses = NumericAddresses(host);
  if (addresses.empty() || !std::all_of(addresses.begin(), addresses.end(), IsLoopback)) return {};
  std::set<std::string> names = {authority};
  // Clients leave the default port out of Host: on port 80 the bare names.
  for (const std::string& suffix : port == 80 ? std::vector<std::string>{":80", ""}
                                              : std::vector<std::string>{":" + std::to_string(port)}) {
    names.insert("localhost" + suffix);
    for (const std::string& a : addresses)
      names.insert(a.find(':') != std::string::npos ? "[" + a + "]" + suffix : a + suffix);
  }
  return names;
}

// Read-only: any other method is a 405 naming the allowed ones.
void SendNotAllowed(const httplib::Request& req, httplib::Response& res) {
  res.set_header("Allow", "GET, HEAD");
  SendError(req, res, 405, req.method + " is not allowed: the server only reads (GET, HEAD)");
}

std::string Lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

}  // namespace

void Serve(const ServeOptions& options, const std::function<void(const std::string&)>& on_listening) {
  StoreReader check(options.dir);  // a missing or foreign store is said before binding
  CheckAsset(std::string(ICPBENCH_WEB_ASSETS) + "/index.html");
  CheckAsset(ICPBENCH_CHART_JS);

  // SIGINT and SIGTERM go to the waiting thread only (the server's threads inherit the mask).
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  httplib::Server server;
  server.set_tcp_nodelay(true);  // no 40 ms Nagle delay on small answers
  // Idle keep-alive connections each hold a thread: with cpp-httplib's 8 and
  // 5 s, 20 idle ones (a browser's, a script's) stalled every request for
  // seconds. More threads, shorter idles.
  server.new_task_queue = [] { return new httplib::ThreadPool(32); };
  server.set_keep_alive_timeout(1);
  server.set_read_timeout(3, 0);
  RegisterRunsApi(server, options.dir);
  RegisterEstimateApi(server, options.dir);
  RegisterCompareApi(server, options.dir);
  RegisterFiles(server, options.dir, ICPBENCH_WEB_ASSETS, ICPBENCH_CHART_JS);
  server.Post(".*", SendNotAllowed);
  server.Put(".*", SendNotAllowed);
  server.Patch(".*", SendNotAllowed);
  server.Delete(".*", SendNotAllowed);
  server.Options(".*", SendNotAllowed);
  server.set_exception_handler([](const httplib::Request& req, httplib::Response& res, std::exception_ptr e) {
    try {
      std::rethrow_exception(e);
    } catch (const HttpError& error) {
      SendError(req, res, error.status, error.what());
    } catch (const std::exception& error) {
      SendError(req, res, 500, error.what());
    }
  });
  server.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    if (res.status == 404) {
      SendError(req, res, 404, "no such page: " + req.path);
    } else if (res.status == 414) {
      SendError(req, res, 414, "the URL is too long");
    } else if (res.status == 413) {
      SendError(req, res, 413, "the request has a body: the server takes none");
    } else if (res.status == 400 && req.method != "GET" && req.method != "HEAD") {
      // cpp-httplib refuses a method it does not know, or a POST without a
      // body, before routing: still a method the server does not allow.
      SendNotAllowed(req, res);
    } else {
      SendError(req, res, res.status, "bad request (HTTP status " + std::to_string(res.status) + ")");
    }
  });
  // The API takes no body: a large one (1 GiB to a GET or a POST) was read
  // whole into memory before the answer.
  server.set_payload_max_length(64 * 1024);

  // cpp-httplib's default sets SO_REUSEPORT, with which a second server
  // binds a port in use and the kernel splits the requests between the two
  // stores: SO_REUSEADDR alone only allows rebinding after a restart.
  server.set_socket_options([](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, reinterpret_cast<void*>(&yes), sizeof yes);
  });
  // An empty host would print an unusable URL (http://:PORT/) and bind ::1.
  if (options.host.empty()) throw std::invalid_argument("serve: --host must not be empty");
  int port = options.port;
  if (port == 0) {
    port = server.bind_to_any_port(options.host);
    if (port < 0) throw EnvironmentError("cannot bind a port on host '" + options.host + "'");
  } else if (!server.bind_to_port(options.host, port)) {
    throw EnvironmentError("cannot bind " + options.host + ":" + std::to_string(port) +
                           " (in use, or not an address of this machine)");
  }
  const bool ipv6 = options.host.find(':') != std::string::npos;
  const std::string authority =
      (ipv6 ? "[" + options.host + "]" : options.host) + ":" + std::to_string(port);
  // On a loopback address only this machine's own names are answered: a web
  // page elsewhere that rebinds its DNS name to 127.0.0.1 cannot read the store.
  // Host names are compared in lower case, as DNS does.
  std::set<std::string> names;  // empty: any Host
  for (const std::string& name : LoopbackHostNames(options.host, authority, port))
    names.insert(Lowercase(name));
  server.set_pre_routing_handler([names](const httplib::Request& req, httplib::Response& res) {
    if (!names.empty() && names.count(Lowercase(req.get_header_value("Host"))) == 0) {
      SendError(req, res, 403, "host '" + req.get_header_value("Host") + "' not served (use " +
                                   *names.begin() + ")");
      return httplib::Server::HandlerResponse::Handled;
    }
    // Many ranges of one body would multiply it in the answer (300 ranges of
    // a 200 kB figure: 60 MB built in memory); one range is enough to resume.
    if (req.get_header_value("Range").find(',') != std::string::npos) {
      SendError(req, res, 416, "one byte range per request");
      return httplib::Server::HandlerResponse::Handled;
    }
    if (const std::string problem = BadQuery(req); !problem.empty()) {
      SendError(req, res, 400, problem);
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  on_listening("http://" + authority + "/");

  // The first signal stops the server, which waits for the re-runs in
  // progress (up to 10 s each); a second one does not wait.
  std::atomic<bool> finished{false};
  std::thread waiter([&server, &finished, stop_signals] {
    int signal = 0;
    sigwait(&stop_signals, &signal);
    if (finished) return;
    server.stop();
    sigwait(&stop_signals, &signal);
    if (finished) return;
    std::fputs("icpbench serve: a second signal: stopped without waiting for the re-runs in progress\n",
               stderr);
    std::_Exit(128 + signal);
  });
  server.listen_after_bind();
  // Stopped, or listen_after_bind returned by itself (a socket error): the
  // waiter, in one of its waits, is woken to end.
  finished = true;
  pthread_kill(waiter.native_handle(), SIGTERM);
  waiter.join();
}

}  // namespace icp::web
