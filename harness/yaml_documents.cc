#include "harness/yaml_documents.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <sstream>

namespace icp {

namespace {

// Notes where the second document's first content event is.
class SecondDocumentFinder : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}  // empty: harmless
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { Content(mark); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                const std::string&) override {
    Content(mark);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    Content(mark);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    Content(mark);
  }
  void OnMapEnd() override {}

  int document = 0;  // 0 while the first is read, 1 for the second
  std::optional<YAML::Mark> second;

 private:
  void Content(const YAML::Mark& mark) {
    if (document == 1 && !second) second = mark;
  }
};

}  // namespace

std::optional<YAML::Mark> SecondDocumentMark(const std::string& text) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  SecondDocumentFinder finder;
  if (!parser.HandleNextDocument(finder)) return std::nullopt;
  ++finder.document;
  if (!parser.HandleNextDocument(finder)) return std::nullopt;
  return finder.second;
}

bool IndentationHasATab(const std::string& text, int line) {
  std::size_t start = 0;
  for (int i = 0; i < line && start != std::string::npos; ++i) {
    start = text.find('\n', start);
    if (start != std::string::npos) ++start;
  }
  if (start == std::string::npos) return false;
  const std::size_t first = text.find_first_not_of(" \t", start);
  return text.find('\t', start) < (first == std::string::npos ? text.size() : first);
}

}  // namespace icp
