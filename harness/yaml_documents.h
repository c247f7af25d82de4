// Where a second YAML document starts, found without YAML::LoadAll: yaml-cpp
// 0.7's parser returns an endless run of empty documents on a stray ','
// (LoadAll never returns; found by the spec fuzzer), so the parser is asked
// for two documents and no more.
#ifndef ICPBENCH_HARNESS_YAML_DOCUMENTS_H_
#define ICPBENCH_HARNESS_YAML_DOCUMENTS_H_

#include <yaml-cpp/mark.h>

#include <optional>
#include <string>

namespace icp {

// Where text's second document starts if it has content (an empty one, as a
// trailing '---' makes, is nullopt too); throws YAML::ParserException on
// text that does not parse.
std::optional<YAML::Mark> SecondDocumentMark(const std::string& text);

// Whether line `line` (0-based) of text has a tab before its first other
// character: yaml-cpp's "illegal block entry" and the like, said plainly.
bool IndentationHasATab(const std::string& text, int line);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_YAML_DOCUMENTS_H_
