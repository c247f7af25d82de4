#include "core/near_names.h"

#include <algorithm>
#include <cctype>
#include <cstddef>

namespace icp {
namespace {

bool SameLetter(char a, char b) {
  return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
}

// Optimal string alignment distance (Damerau-Levenshtein without repeated
// edits of a substring): a swapped pair of letters, the commonest typo,
// costs 1; case is ignored (HC4 is hc4 written as the paper writes it).
std::size_t EditDistance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t substitution = d[i - 1][j - 1] + !SameLetter(a[i - 1], b[j - 1]);
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, substitution});
      if (i > 1 && j > 1 && SameLetter(a[i - 1], b[j - 2]) && SameLetter(a[i - 2], b[j - 1]))
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

}  // namespace

std::string DidYouMean(std::string_view name, const std::vector<std::string>& candidates) {
  // Names are short; a long unknown one (pasted text) is not a typo.
  constexpr std::size_t kLongest = 64;
  if (name.empty() || name.size() > kLongest) return "";
  const std::size_t limit = std::max<std::size_t>(1, name.size() / 3);
  std::size_t best = limit + 1;
  const std::string* match = nullptr;
  bool tied = false;
  for (const std::string& c : candidates) {
    if (c.size() > kLongest || c == name) continue;
    const std::size_t d = EditDistance(name, c);
    if (d < best) {
      best = d;
      match = &c;
      tied = false;
    } else if (d == best) {
      tied = true;
    }
  }
  if (!match || tied) return "";
  return "; did you mean '" + *match + "'?";
}

}  // namespace icp
