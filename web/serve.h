// `icpbench serve DIR`: the results browser. A read-only HTTP server over the
// results store of DIR (a JSON API, web/api_*.cc) and one static page
// (web/assets, Debian's Chart.js); docs/web.md.
#ifndef ICPBENCH_WEB_SERVE_H_
#define ICPBENCH_WEB_SERVE_H_

#include <functional>
#include <string>

namespace icp::web {

struct ServeOptions {
  std::string dir;                // output directory of `icpbench run`
  std::string host = "127.0.0.1";  // localhost unless told otherwise
  int port = 0;                   // 0: a free port
};

// Checks DIR's store, binds host:port and calls on_listening with the page's
// URL, then serves until SIGINT or SIGTERM. Throws StoreError (bad input) for
// a missing or foreign store, EnvironmentError when the address cannot be
// bound.
void Serve(const ServeOptions& options, const std::function<void(const std::string&)>& on_listening);

}  // namespace icp::web

#endif  // ICPBENCH_WEB_SERVE_H_
