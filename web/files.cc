// The page's own assets (index.html, app.js, style.css, Debian's Chart.js),
// GET /api/figures and /figures/NAME (what `icpbench plot` wrote into
// DIR/figures) and GET /api/claims (DIR/paper/claims.json, if present).
// Nothing outside DIR/figures, DIR/paper/claims.json and the assets is ever
// read: a figure's name is checked segment by segment, then its real path
// (symbolic links resolved) must lie inside DIR/figures; claims.json is read
// only as a regular file, not through a link. A figure is served sandboxed.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "web/api.h"

namespace icp::web {

namespace fs = std::filesystem;

namespace {

const std::map<std::string, std::string> kTypes = {
    {".html", "text/html; charset=utf-8"}, {".js", "text/javascript; charset=utf-8"},
    {".css", "text/css; charset=utf-8"},   {".png", "image/png"},
    {".pdf", "application/pdf"},           {".svg", "image/svg+xml"},
    {".csv", "text/csv; charset=utf-8"},   {".json", "application/json"},
    {".md", "text/plain; charset=utf-8"},  {".txt", "text/plain; charset=utf-8"}};

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw HttpError(404, "cannot read '" + path.filename().string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void SendFile(httplib::Response& res, const fs::path& path) {
  auto type = kTypes.find(path.extension().string());
  res.set_content(ReadFile(path), type == kTypes.end() ? "application/octet-stream" : type->second);
}

// What `icpbench plot` writes: PNG, PDF and SVG files.
bool IsFigure(const fs::path& path) {
  const std::string ext = path.extension().string();
  return ext == ".png" || ext == ".pdf" || ext == ".svg";
}

// Whether DIR/figures is the store's own folder, not a symbolic link to
// one elsewhere (whose files the canonical check below would take as inside).
bool FiguresFolderIsOwn(const std::string& dir) {
  std::error_code ec;
  return !fs::is_symlink(fs::symlink_status(fs::path(dir) / "figures", ec));
}

// DIR/figures/NAME if NAME is a relative path of plain segments whose real
// path is a regular file inside DIR/figures; else a 400 or 404.
fs::path FigurePath(const std::string& dir, const std::string& name) {
  std::size_t start = 0;
  while (start <= name.size()) {
    std::size_t slash = name.find('/', start);
    if (slash == std::string::npos) slash = name.size();
    const std::string segment = name.substr(start, slash - start);
    if (segment.empty() || segment[0] == '.' || segment.find('\\') != std::string::npos ||
        segment.find('\0') != std::string::npos)
      throw HttpError(400, "bad figure path '" + name + "' (outside " + dir + "/figures)");
    start = slash + 1;
  }
  std::error_code ec;
  // Not through a symbolic link, the folder's or the file's: what is served
  // is what /api/figures lists, and nothing outside the store.
  if (!FiguresFolderIsOwn(dir)) throw HttpError(404, "no figures in " + dir);
  const fs::path root = fs::canonical(fs::path(dir) / "figures", ec);
  if (ec) throw HttpError(404, "no figures in " + dir);
  if (fs::is_symlink(fs::symlink_status(fs::path(dir) / "figures" / name, ec)))
    throw HttpError(404, "no figure '" + name + "' (a symbolic link is not served)");
  const fs::path file = fs::canonical(root / name, ec);
  if (ec || !fs::is_regular_file(file, ec) || !IsFigure(file)) throw HttpError(404, "no figure '" + name + "'");
  const fs::path relative = file.lexically_relative(root);
  if (relative.empty() || *relative.begin() == "..")
    throw HttpError(400, "bad figure path '" + name + "' (outside " + dir + "/figures)");
  return file;
}

void GetFigures(const std::string& dir, const httplib::Request& req, httplib::Response& res) {
  RequireNoQuery(req);
  nlohmann::json names = nlohmann::json::array();
  std::error_code ec;
  const fs::path root = fs::path(dir) / "figures";
  if (FiguresFolderIsOwn(dir) && fs::is_directory(root, ec)) {
    std::vector<std::string> found;
    for (const auto& e : fs::recursive_directory_iterator(root, ec)) {
      const std::string name = e.path().lexically_relative(root).generic_string();
      // What /figures/NAME serves, and only that: no hidden segment.
      if (!e.is_symlink(ec) && e.is_regular_file(ec) && IsFigure(e.path()) && name[0] != '.' &&
          name.find("/.") == std::string::npos)
        found.push_back(name);
    }
    std::sort(found.begin(), found.end());
    for (const std::string& n : found) names.push_back(n);
  }
  SendJson(res, names);
}

void GetClaims(const std::string& dir, const httplib::Request& req, httplib::Response& res) {
  RequireNoQuery(req);
  const fs::path file = fs::path(dir) / "paper" / "claims.json";
  std::error_code ec;
  // Not through a symbolic link: nothing outside the store is read.
  if (!fs::is_regular_file(fs::symlink_status(file, ec)) ||
      fs::is_symlink(fs::symlink_status(file.parent_path(), ec))) {
    SendJson(res, {{"file", nullptr}, {"claims", nlohmann::json::array()}});
    return;
  }
  nlohmann::json claims = nlohmann::json::parse(ReadFile(file), nullptr, /*exceptions=*/false);
  if (claims.is_discarded()) throw HttpError(500, "paper/claims.json is not JSON");
  SendJson(res, {{"file", "paper/claims.json"}, {"claims", claims}});
}

}  // namespace

void RegisterFiles(httplib::Server& server, const std::string& dir, const std::string& assets,
                   const std::string& chart_js) {
  using namespace std::placeholders;
  const std::map<std::string, fs::path> files = {{"/", fs::path(assets) / "index.html"},
                                                 {"/index.html", fs::path(assets) / "index.html"},
                                                 {"/app.js", fs::path(assets) / "app.js"},
                                                 {"/style.css", fs::path(assets) / "style.css"},
                                                 {"/chart.js", fs::path(chart_js)}};
  for (const auto& [route, path] : files)
    server.Get(route, [path = path](const httplib::Request&, httplib::Response& res) {
      SendFile(res, path);
    });
  server.Get("/api/figures", std::bind(GetFigures, dir, _1, _2));
  server.Get("/api/claims", std::bind(GetClaims, dir, _1, _2));
  server.Get(R"(/figures/(.*))", [dir](const httplib::Request& req, httplib::Response& res) {
    SendFile(res, FigurePath(dir, req.matches[1]));
    // A figure is a picture: an SVG opened on its own would run its scripts
    // with the page's origin (and its API); sandboxed, none runs.
    res.set_header("Content-Security-Policy", "sandbox; default-src 'none'; style-src 'unsafe-inline'; img-src data:");
  });
}

}  // namespace icp::web
