// A shader's code as tokens (docs/brdf-code.md#how-the-shader-runs): what the analysis and the
// translation to C++ read. Comments become spaces that keep their newlines, so that every pass
// keeps the file's line numbers.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace verify {

struct token {
    enum kind { space, word, number, punct, directive } type;
    std::string text;
};

// Comments become spaces (their newlines kept); a # line is one directive token (preprocessed
// code has none). Punctuation is one character a token: ++ is two tokens, side by side.
std::vector<token> tokenize(const std::string& s);

// The tokens with what the passes over them ask: the significant (not space) neighbours of a
// token, the bracket that closes or opens one, the innermost bracket around it, its line.
class token_list {
public:
    static constexpr std::size_t none = static_cast<std::size_t>(-1);
    token_list(std::vector<token> t, int first_line);

    std::size_t size() const { return t_.size(); }
    const token& operator[](std::size_t i) const { return t_[i]; }
    const std::vector<token>& tokens() const { return t_; }
    // The next (previous) token that is not a space, or none.
    std::size_t next(std::size_t i) const;
    std::size_t prev(std::size_t i) const;
    // Token i is `text` (false for none or past the end).
    bool is(std::size_t i, const char* text) const { return i < t_.size() && t_[i].text == text; }
    bool is_word(std::size_t i) const { return i < t_.size() && t_[i].type == token::word; }
    // The bracket matching the one at i ( ( [ { or ) ] } ), or none where it does not balance.
    std::size_t match(std::size_t i) const { return i < match_.size() ? match_[i] : none; }
    // The innermost open bracket around token i, or none at the top level.
    std::size_t parent(std::size_t i) const { return parent_[i]; }
    int line(std::size_t i) const { return line_[i]; }
    // The first bracket that does not balance, or none.
    std::size_t unbalanced() const { return unbalanced_; }

private:
    std::vector<token> t_;
    std::vector<std::size_t> match_, parent_;
    std::vector<int> line_;
    std::size_t unbalanced_ = none;
};

}  // namespace verify
