// Minibex tokenizer: splits the text into identifiers, numbers and
// punctuation with their line and column; comments and whitespace vanish.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "core/minibex_parser_internal.h"

namespace icp::detail::minibex {
namespace {

// Splits text into tokens; comments and whitespace vanish, positions are
// 1-based lines and byte columns.
class Tokenizer {
 public:
  Tokenizer(const std::string& text, const std::string& source) : s_(text), source_(source) {}

  std::vector<Token> Run() {
    std::vector<Token> out;
    // Editors on Windows start UTF-8 files with a byte order mark; it is not
    // part of the text (columns still count from the first real character).
    if (s_.starts_with(kUtf8ByteOrderMark)) i_ = kUtf8ByteOrderMark.size();
    while (i_ < s_.size()) {
      const char c = s_[i_];
      const char next = i_ + 1 < s_.size() ? s_[i_ + 1] : '\0';
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
        Advance(1);
      } else if (c == '/' && next == '/') {
        while (i_ < s_.size() && s_[i_] != '\n') Advance(1);
      } else if (c == '/' && next == '*') {
        SkipBlockComment();
      } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
        out.push_back(Take(TokKind::kIdent, IdentLength()));
      } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                 (c == '.' && std::isdigit(static_cast<unsigned char>(next)))) {
        out.push_back(Take(TokKind::kNumber, NumberLength()));
      } else if (c == '#' && std::isxdigit(static_cast<unsigned char>(next))) {
        out.push_back(Take(TokKind::kNumber, HexLength()));
      } else if ((c == '<' || c == '>') && next == '=') {
        out.push_back(Take(TokKind::kPunct, 2));
      } else if (std::string_view("+-*/^()[],;:=<>").find(c) != std::string_view::npos) {
        out.push_back(Take(TokKind::kPunct, 1));
      } else {
        char what[48];
        if (std::isprint(static_cast<unsigned char>(c)))
          std::snprintf(what, sizeof what, "unexpected character '%c'", c);
        else
          std::snprintf(what, sizeof what, "unexpected byte 0x%02X",
                        static_cast<unsigned>(static_cast<unsigned char>(c)));
        throw MinibexError(source_, line_, column_, what);
      }
    }
    out.push_back(Token{TokKind::kEnd, "", line_, column_});
    return out;
  }

 private:
  static constexpr std::string_view kUtf8ByteOrderMark = "\xEF\xBB\xBF";

  bool IsIdentChar(std::size_t k) const {
    return k < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[k])) || s_[k] == '_');
  }
  bool IsDigit(std::size_t k) const {
    return k < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k]));
  }

  void Advance(std::size_t n) {
    for (std::size_t k = 0; k < n && i_ < s_.size(); ++k, ++i_) {
      if (s_[i_] == '\n') {
        ++line_;
        column_ = 1;
      } else {
        ++column_;
      }
    }
  }

  Token Take(TokKind kind, std::size_t length) {
    Token t{kind, s_.substr(i_, length), line_, column_};
    Advance(length);
    return t;
  }

  void SkipBlockComment() {
    const int line = line_, column = column_;
    Advance(2);
    while (i_ < s_.size() && !(s_[i_] == '*' && i_ + 1 < s_.size() && s_[i_ + 1] == '/'))
      Advance(1);
    if (i_ >= s_.size()) throw MinibexError(source_, line, column, "unterminated /* comment");
    Advance(2);
  }

  std::size_t IdentLength() const {
    std::size_t k = i_;
    while (IsIdentChar(k)) ++k;
    return k - i_;
  }

  // digits [. digits] [e [+-] digits]; a letter, digit or dot glued to the
  // end (as in "2x", "1e", "1.2.3") makes the whole word a bad number.
  std::size_t NumberLength() const {
    std::size_t k = i_;
    while (IsDigit(k)) ++k;
    if (k < s_.size() && s_[k] == '.') {
      ++k;
      while (IsDigit(k)) ++k;
    }
    if (k < s_.size() && (s_[k] == 'e' || s_[k] == 'E')) {
      std::size_t e = k + 1;
      if (e < s_.size() && (s_[e] == '+' || s_[e] == '-')) ++e;
      if (IsDigit(e)) {
        k = e;
        while (IsDigit(k)) ++k;
      }
    }
    if (IsIdentChar(k) || (k < s_.size() && s_[k] == '.')) {
      std::size_t end = k;
      while (IsIdentChar(end) || (end < s_.size() && s_[end] == '.')) ++end;
      const std::size_t shown = std::min<std::size_t>(end - i_, 40);
      throw MinibexError(source_, line_, column_, "bad number '" + s_.substr(i_, shown) + "'");
    }
    return k - i_;
  }

  // '#' and hexadecimal digits (IBEX's exact double); a letter or digit
  // glued to the end makes it a bad number.
  std::size_t HexLength() const {
    std::size_t k = i_ + 1;
    while (k < s_.size() && std::isxdigit(static_cast<unsigned char>(s_[k]))) ++k;
    if (IsIdentChar(k)) {
      std::size_t end = k;
      while (IsIdentChar(end)) ++end;
      throw MinibexError(source_, line_, column_,
                         "bad number '" + s_.substr(i_, std::min<std::size_t>(end - i_, 40)) + "'");
    }
    return k - i_;
  }

  const std::string& s_;
  const std::string& source_;
  std::size_t i_ = 0;
  int line_ = 1;
  int column_ = 1;
};

}  // namespace

std::vector<Token> Tokenize(const std::string& text, const std::string& source) {
  return Tokenizer(text, source).Run();
}

}  // namespace icp::detail::minibex
