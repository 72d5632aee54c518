// WGSL's statements and expressions (https://www.w3.org/TR/WGSL/#statements,
// #expression-grammar): precedence as the grammar gives it, and what it refuses (a < b < c,
// a && b || c and a & b | c without parentheses) refused here too.
#include "wgsl_parser.hpp"

namespace verify::wgsl {

namespace {
bool comparison(const token& t) {
    return t.k == token::kind::punct && (t.text == "<" || t.text == ">" || t.text == "<=" || t.text == ">=" || t.text == "==" || t.text == "!=");
}
bool is(const token& t, const char* text) { return t.k == token::kind::punct && t.text == text; }
}  // namespace

int parser::block(int& depth) {
    stmt s;
    s.k = stmt::kind::block;
    s.line = peek().line;
    expect("{", "to begin a block");
    enter(depth);
    while (!is(peek(), "}")) {
        if (peek().k == token::kind::end) fail(peek().line, "a block that does not end: expected '}'");
        if (accept(";")) continue;  // an empty statement: nothing to keep
        s.body.push_back(statement(depth));
    }
    s.end_line = peek().line;
    ++at_;
    --depth;
    return add(s);
}

int parser::statement(int& depth) {
    for (const auto& a : attributes())  // @diagnostic(...) changes no meaning; WGSL has no other here
        if (a.name != "diagnostic") fail(a.line, "@" + a.name + " is no attribute of a statement");
    const token& t = peek();
    stmt s;
    s.line = t.line;
    if (is(t, ";")) {
        ++at_;
        return add(s);
    }
    if (is(t, "{")) return block(depth);
    if (t.k == token::kind::ident) {
        const std::string w = t.text;
        if (w == "if") return if_statement(depth);
        if (w == "loop") return loop_statement(depth);
        if (w == "for") return for_statement(depth);
        if (w == "switch") return switch_statement(depth);
        if (w == "while") {
            ++at_;
            s.k = stmt::kind::while_;
            s.value = expression();
            s.body.push_back(block(depth));
            return add(s);
        }
        if (w == "return" || w == "break" || w == "continue" || w == "discard" || w == "const_assert") {
            ++at_;
            s.k = w == "return" ? stmt::kind::return_ : w == "continue" ? stmt::kind::continue_ : w == "discard" ? stmt::kind::discard
                : w == "const_assert" ? stmt::kind::const_assert : stmt::kind::break_;
            if (s.k == stmt::kind::break_ && word("if")) ++at_, s.k = stmt::kind::break_if;
            if ((s.k == stmt::kind::return_ && !is(peek(), ";")) || s.k == stmt::kind::const_assert || s.k == stmt::kind::break_if)
                s.value = expression();
            expect(";", "after " + w);
            return add(s);
        }
        if (w == "var" || w == "let" || w == "const") {
            const int d = declaration_statement();
            expect(";", "after the declaration of " + stmts_[static_cast<std::size_t>(d)].name);
            return d;
        }
    }
    const int d = simple_statement();
    expect(";", "after the statement");
    return d;
}

int parser::if_statement(int& depth) {
    stmt s;
    s.k = stmt::kind::if_;
    s.line = peek().line;
    ++at_;  // if
    s.value = expression();
    s.body.push_back(block(depth));
    if (word("else")) {
        ++at_;
        if (word("if")) {
            enter(depth);
            s.else_ = if_statement(depth);
            --depth;
        } else {
            s.else_ = block(depth);
        }
    }
    return add(s);
}

int parser::loop_statement(int& depth) {
    stmt s;
    s.k = stmt::kind::loop;
    s.line = peek().line;
    ++at_;  // loop
    attributes();
    expect("{", "after loop");
    enter(depth);
    while (!is(peek(), "}")) {
        if (peek().k == token::kind::end) fail(peek().line, "a loop that does not end: expected '}'");
        if (word("continuing")) {
            s.has_continuing = true;
            s.continuing_line = peek().line;
            ++at_;
            attributes();
            const int b = block(depth);
            s.continuing = stmts_[static_cast<std::size_t>(b)].body;
            if (!is(peek(), "}")) fail(peek().line, "the continuing block must be the last in its loop");
            break;
        }
        s.body.push_back(statement(depth));
    }
    s.end_line = peek().line;
    ++at_;
    --depth;
    return add(s);
}

int parser::for_statement(int& depth) {
    stmt s;
    s.k = stmt::kind::for_;
    s.line = peek().line;
    ++at_;  // for
    expect("(", "after for");
    if (!is(peek(), ";")) s.init = word("var") || word("let") || word("const") ? declaration_statement() : simple_statement();
    expect(";", "after the for loop's initializer");
    if (!is(peek(), ";")) s.value = expression();
    expect(";", "after the for loop's condition");
    if (!is(peek(), ")")) s.update = simple_statement();
    expect(")", "to close for (...)");
    s.body.push_back(block(depth));
    return add(s);
}

int parser::switch_statement(int& depth) {
    stmt s;
    s.k = stmt::kind::switch_;
    s.line = peek().line;
    ++at_;  // switch
    s.value = expression();
    attributes();
    expect("{", "after switch's selector");
    while (!is(peek(), "}")) {
        if (word("case")) {
            ++at_;
            while (!is(peek(), ":") && !is(peek(), "{")) {
                if (word("default")) ++at_;
                else s.templ.push_back(expression());
                if (!accept(",")) break;
            }
        } else if (word("default")) {
            ++at_;
        } else {
            fail(peek().line, "expected case or default in switch, found " + shown(peek()));
        }
        accept(":");
        s.body.push_back(block(depth));
    }
    s.end_line = peek().line;
    ++at_;
    return add(s);
}

int parser::declaration_statement() {
    stmt s;
    s.line = peek().line;
    const std::string w = peek().text;
    ++at_;
    s.k = w == "var" ? stmt::kind::var : w == "let" ? stmt::kind::let : stmt::kind::const_;
    if (s.k == stmt::kind::var) {
        expr holder;
        template_list(holder);
        s.templ = holder.templ;
    }
    typed_name(s.name, s.type, "a name after '" + w + "'");
    if (s.k != stmt::kind::var || is(peek(), "=")) {
        expect("=", "after " + w + " " + s.name + " (a " + w + " has a value)");
        s.value = expression();
    }
    return add(s);
}

int parser::simple_statement() {
    stmt s;
    s.line = peek().line;
    if (accept("_")) {
        s.k = stmt::kind::assign;
        s.name = "_";
        expect("=", "after '_' (the phony assignment _ = e)");
        s.value = expression();
        return add(s);
    }
    const int e = expression();
    const token& t = peek();
    static const char* const assignments[] = {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>="};
    for (const char* a : assignments)
        if (is(t, a)) {
            ++at_;
            s.k = stmt::kind::assign;
            s.name = a;
            s.target = e;
            s.value = expression();
            return add(s);
        }
    if (is(t, "++") || is(t, "--")) {
        ++at_;
        s.k = t.text == "++" ? stmt::kind::increment : stmt::kind::decrement;
        s.target = e;
        return add(s);
    }
    if (exprs_[static_cast<std::size_t>(e)].k != expr::kind::call || exprs_[static_cast<std::size_t>(e)].parenthesized)
        fail(s.line, "this expression is no statement: a statement assigns (=, +=, ...), increments (++, --) or calls a function");
    s.k = stmt::kind::call;
    s.value = e;
    return add(s);
}

int parser::binary(const std::string& op, int a, int b, int line) {
    expr e;
    e.k = expr::kind::binary;
    e.text = op;
    e.line = line;
    e.args = {a, b};
    return add(e);
}

int parser::expression() {
    enter(expr_depth_);
    const int line = peek().line;
    int lhs = unary();
    const token& t = peek();
    if (is(t, "&") || is(t, "|") || is(t, "^")) {
        const std::string op = t.text;
        while (accept(op)) lhs = binary(op, lhs, unary(), line);
        if (is(peek(), "&") || is(peek(), "|") || is(peek(), "^") || is(peek(), "&&") || is(peek(), "||") || comparison(peek()))
            fail(peek().line, "WGSL needs parentheses to mix '" + op + "' with '" + peek().text + "'");
        --expr_depth_;
        return lhs;
    }
    lhs = relational_rest(lhs);
    if (is(peek(), "&&") || is(peek(), "||")) {
        const std::string op = peek().text;
        while (accept(op)) lhs = binary(op, lhs, relational_rest(unary()), line);
        if (is(peek(), "&&") || is(peek(), "||")) fail(peek().line, "WGSL needs parentheses to mix '&&' and '||'");
    }
    if (comparison(peek())) fail(peek().line, "WGSL needs parentheses around a comparison compared again ('" + peek().text + "')");
    --expr_depth_;
    return lhs;
}

int parser::relational_rest(int lhs) {
    const int line = peek().line;
    lhs = shift_rest(lhs);
    if (!comparison(peek())) return lhs;
    const std::string op = peek().text;
    ++at_;
    return binary(op, lhs, shift_rest(unary()), line);
}

int parser::shift_rest(int lhs) {
    if (is(peek(), "<<") || is(peek(), ">>")) {
        const std::string op = peek().text;
        const int line = peek().line;
        ++at_;
        return binary(op, lhs, unary(), line);
    }
    return additive_rest(lhs);
}

int parser::additive_rest(int lhs) {
    lhs = multiplicative_rest(lhs);
    while (is(peek(), "+") || is(peek(), "-")) {
        const std::string op = peek().text;
        const int line = peek().line;
        ++at_;
        lhs = binary(op, lhs, multiplicative_rest(unary()), line);
    }
    return lhs;
}

int parser::multiplicative_rest(int lhs) {
    while (is(peek(), "*") || is(peek(), "/") || is(peek(), "%")) {
        const std::string op = peek().text;
        const int line = peek().line;
        ++at_;
        lhs = binary(op, lhs, unary(), line);
    }
    return lhs;
}

int parser::unary() {
    const token& t = peek();
    if (is(t, "-") || is(t, "!") || is(t, "~") || is(t, "*") || is(t, "&")) {
        enter(expr_depth_);
        expr e;
        e.k = expr::kind::unary;
        e.text = t.text;
        e.line = t.line;
        ++at_;
        e.args = {unary()};
        --expr_depth_;
        return add(e);
    }
    return singular();
}

int parser::singular() {
    int e = primary();
    while (true) {
        const int line = peek().line;
        if (accept("[")) {
            expr x;
            x.k = expr::kind::index;
            x.line = line;
            x.args = {e, expression()};
            expect("]", "to close [...]");
            e = add(x);
        } else if (accept(".")) {
            expr x;
            x.k = expr::kind::member;
            x.line = line;
            if (peek().k != token::kind::ident) fail(peek().line, "expected a member's name after '.', found " + shown(peek()));
            x.text = peek().text;
            ++at_;
            x.args = {e};
            e = add(x);
        } else {
            return e;
        }
    }
}

int parser::primary() {
    const token& t = peek();
    expr e;
    e.line = t.line;
    e.text = t.text;
    if (t.k == token::kind::int_literal || t.k == token::kind::float_literal) {
        e.k = t.k == token::kind::int_literal ? expr::kind::int_literal : expr::kind::float_literal;
        ++at_;
        return add(e);
    }
    if (accept("(")) {
        const int inner = expression();
        expect(")", "to close (...)");
        exprs_[static_cast<std::size_t>(inner)].parenthesized = true;
        return inner;
    }
    if (t.k != token::kind::ident) fail(t.line, "expected an expression, found " + shown(t));
    if (t.text == "true" || t.text == "false") {
        e.k = expr::kind::bool_literal;
        ++at_;
        return add(e);
    }
    e.k = expr::kind::name;
    e.text = name("a name");
    template_list(e);
    if (accept("(")) {
        e.k = expr::kind::call;
        while (!accept(")")) {
            e.args.push_back(expression());
            if (!accept(",")) {
                expect(")", "to close " + e.text + "(...)");
                break;
            }
        }
    }
    return add(e);
}

}  // namespace verify::wgsl
