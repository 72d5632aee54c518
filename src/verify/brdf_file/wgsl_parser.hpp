// The recursive-descent reader of WGSL (wgsl_syntax.hpp): declarations in wgsl_parse.cpp,
// statements and expressions in wgsl_parse_body.cpp.
#pragma once
#include <string>
#include <vector>

#include "wgsl_syntax.hpp"

namespace verify::wgsl {

class parser {
public:
    parser(std::string path, const std::vector<token>& tokens) : path_(std::move(path)), t_(tokens) {}
    module parse_module();

private:
    std::string path_;
    const std::vector<token>& t_;
    std::size_t at_ = 0;
    std::vector<expr> exprs_;
    std::vector<stmt> stmts_;
    int expr_depth_ = 0;

    const token& peek(std::size_t ahead = 0) const {
        const std::size_t i = at_ + ahead;
        return i < t_.size() ? t_[i] : t_.back();
    }
    [[noreturn]] void fail(int line, const std::string& what) const;
    static std::string shown(const token& t);
    void expect(const std::string& text, const std::string& where);
    bool accept(const std::string& text);
    bool word(const std::string& w) const;
    std::string name(const std::string& what);
    void enter(int& depth);
    int add(const expr& e) {
        exprs_.push_back(e);
        return static_cast<int>(exprs_.size()) - 1;
    }
    int add(const stmt& s) {
        stmts_.push_back(s);
        return static_cast<int>(stmts_.size()) - 1;
    }

    // declarations
    std::vector<attribute> attributes();
    int type_specifier();
    void template_list(expr& e);
    void typed_name(std::string& n, int& type, const std::string& what);
    int parse_function(declaration& d);
    void parse_struct(declaration& d);
    declaration global_declaration();
    static std::string not_a_declaration(const std::string& w);

    // statements
    int block(int& depth);
    int statement(int& depth);
    int if_statement(int& depth);
    int loop_statement(int& depth);
    int for_statement(int& depth);
    int switch_statement(int& depth);
    int declaration_statement();
    int simple_statement();  // an assignment, increment, call or phony assignment, without its ';'

    // expressions (#expression-grammar)
    int expression();
    int relational_rest(int lhs);
    int shift_rest(int lhs);
    int additive_rest(int lhs);
    int multiplicative_rest(int lhs);
    int unary();
    int singular();
    int primary();
    int binary(const std::string& op, int a, int b, int line);
};

}  // namespace verify::wgsl
