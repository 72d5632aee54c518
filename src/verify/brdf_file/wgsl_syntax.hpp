// A WGSL file's text as tokens and as a syntax tree (docs/brdf-code.md#wgsl): the grammar of the
// W3C WGSL specification (https://www.w3.org/TR/WGSL/), template lists found by its own algorithm
// (#template-list-discovery), read whole, so that what lies outside the subset normzoo runs is
// refused by name by the checker (wgsl_check.hpp) rather than misread. Bad input throws bad_input
// "PATH:LINE: ..." in a WGSL programmer's words.
#pragma once
#include <string>
#include <vector>

namespace verify::wgsl {

struct token {
    enum class kind { ident, int_literal, float_literal, punct, template_start, template_end, end };
    kind k = kind::end;
    std::string text;
    int line = 0;
};

// The tokens of `code` (its first line is the file's line `first_line`): comments (nested block
// comments too) dropped; bytes WGSL reads otherwise than a line-by-line reader (a lone carriage
// return, a vertical tab, a form feed, NEL and the Unicode line separators) refused anywhere, and
// anything but ASCII refused outside comments.
// More than max_tokens is refused with `cap` (what the caller's cap is called) in the message.
std::vector<token> tokenize(const std::string& path, const std::string& code, int first_line, std::size_t max_tokens,
                            const std::string& cap);

// How deep expressions and statements may nest: WGSL lets an implementation limit it (its brace
// nesting limit is 127), and a recursive reader must not run out of stack on hostile input.
constexpr int max_nesting = 64;

// An expression. Types are expressions too (vec3<f32> is the name vec3 with a template list).
struct expr {
    enum class kind { int_literal, float_literal, bool_literal, name, call, index, member, unary, binary };
    kind k = kind::name;
    int line = 0;
    std::string text;       // the literal as written, the name, the member, the operator
    std::vector<int> args;  // a call's arguments, an operator's operands, [base, index], [base]
    std::vector<int> templ; // a name's (or a call's callee's) template list
    bool has_templ = false; // written with <...> (possibly to be refused)
    bool parenthesized = false;
};

struct attribute {
    std::string name;
    std::vector<int> args;
    int line = 0;
};

struct stmt {
    enum class kind {
        empty, block, return_, if_, loop, for_, while_, call, var, let, const_, assign, increment, decrement,
        break_, break_if, continue_, discard, const_assert, switch_
    };
    kind k = kind::empty;
    int line = 0, end_line = 0;  // end_line: a block's closing brace
    std::string name;            // a declared name; an assignment's operator (=, +=, ...)
    int type = -1;               // a declaration's type, if written
    int value = -1;              // initializer, returned value, condition, right-hand side, call
    int target = -1;             // an assignment's left-hand side; -1 with name "_" (phony)
    std::vector<int> templ;      // var<...>
    std::vector<int> body;       // a block's statements; a loop's body
    int else_ = -1;              // an if's else (a block or an if)
    int init = -1, update = -1;  // a for's
    std::vector<int> continuing; // a loop's continuing block
    bool has_continuing = false;
    int continuing_line = 0;
};

struct param {
    std::string name;
    int type = -1;
    int line = 0;
    std::vector<attribute> attrs;
};

struct declaration {
    enum class kind { function, structure, const_, var, override_, alias, const_assert };
    kind k = kind::function;
    std::string name;
    int line = 0, end_line = 0;
    std::vector<attribute> attrs;
    std::vector<param> params;  // a function's; a struct's members
    int type = -1;              // a function's return type, a variable's or constant's type, an alias's
    std::vector<attribute> return_attrs;
    int value = -1;             // an initializer; a const_assert's expression
    std::vector<int> templ;     // var<uniform>
    int body = -1;              // a function's block
};

// A directive (enable, requires, diagnostic) before the declarations.
struct directive {
    std::string name;
    std::vector<std::string> words;
    int line = 0;
};

struct module {
    std::vector<directive> directives;
    std::vector<declaration> decls;
    std::vector<expr> exprs;
    std::vector<stmt> stmts;
};

module parse(const std::string& path, const std::vector<token>& tokens);

// WGSL's keywords and reserved words: never a name (#keyword-summary, #reserved-words).
bool reserved(const std::string& word);

}  // namespace verify::wgsl
