#include "shader_tokens.hpp"

#include <algorithm>
#include <cctype>

namespace verify {

std::vector<token> tokenize(const std::string& s) {
    std::vector<token> out;
    std::size_t i = 0;
    bool line_start = true;
    while (i < s.size()) {
        const char c = s[i];
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            while (i < s.size() && s[i] != '\n') ++i;
            continue;
        }
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            std::string kept = " ";
            i += 2;
            while (i + 1 < s.size() && !(s[i] == '*' && s[i + 1] == '/')) kept += s[i] == '\n' ? "\n" : "", ++i;
            i += 2;
            out.push_back({token::space, kept});
            continue;
        }
        if (std::isspace(static_cast<unsigned char>(c))) {
            out.push_back({token::space, std::string(1, c)});
            if (c == '\n') line_start = true;
            ++i;
            continue;
        }
        if (c == '#' && line_start) {
            std::size_t j = s.find('\n', i);
            if (j == std::string::npos) j = s.size();
            out.push_back({token::directive, s.substr(i, j - i)});
            i = j;
            continue;
        }
        line_start = false;
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            std::size_t j = i;
            while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
            out.push_back({token::word, s.substr(i, j - i)});
            i = j;
            continue;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
            std::size_t j = i;
            while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '.' ||
                                    ((s[j] == '+' || s[j] == '-') && (s[j - 1] == 'e' || s[j - 1] == 'E'))))
                ++j;
            out.push_back({token::number, s.substr(i, j - i)});
            i = j;
            continue;
        }
        out.push_back({token::punct, std::string(1, c)});
        ++i;
    }
    return out;
}

token_list::token_list(std::vector<token> t, int first_line)
    : t_(std::move(t)), match_(t_.size(), none), parent_(t_.size(), none), line_(t_.size(), first_line) {
    std::vector<std::size_t> open;
    int line = first_line;
    for (std::size_t i = 0; i < t_.size(); ++i) {
        line_[i] = line;
        line += static_cast<int>(std::count(t_[i].text.begin(), t_[i].text.end(), '\n'));
        parent_[i] = open.empty() ? none : open.back();
        if (t_[i].type != token::punct) continue;
        const char c = t_[i].text[0];
        if (c == '(' || c == '[' || c == '{') {
            open.push_back(i);
        } else if (c == ')' || c == ']' || c == '}') {
            const char want = c == ')' ? '(' : c == ']' ? '[' : '{';
            if (open.empty() || t_[open.back()].text[0] != want) {
                if (unbalanced_ == none) unbalanced_ = i;
                continue;
            }
            match_[i] = open.back();
            match_[open.back()] = i;
            open.pop_back();
            parent_[i] = open.empty() ? none : open.back();
        }
    }
    if (unbalanced_ == none && !open.empty()) unbalanced_ = open.front();
}

std::size_t token_list::next(std::size_t i) const {
    if (i == none) return none;
    for (std::size_t j = i + 1; j < t_.size(); ++j)
        if (t_[j].type != token::space) return j;
    return none;
}

std::size_t token_list::prev(std::size_t i) const {
    if (i == none || i > t_.size()) return none;
    for (std::size_t j = i; j-- > 0;)
        if (t_[j].type != token::space) return j;
    return none;
}

}  // namespace verify
