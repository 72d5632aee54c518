#include "shader_messages.hpp"

#include <cctype>
#include <sstream>

namespace verify {

namespace {

// "<digits>:" at `from` in `l`: the number, and the rest after the colon, trimmed.
bool numbered(const std::string& l, std::size_t from, int& line, std::string& rest) {
    std::size_t i = from;
    while (i < l.size() && std::isdigit(static_cast<unsigned char>(l[i]))) ++i;
    if (i == from || i - from > 9 || i + 1 >= l.size() || l[i] != ':') return false;
    line = std::stoi(l.substr(from, i - from));
    rest = l.substr(i + 1);
    while (!rest.empty() && rest.front() == ' ') rest.erase(rest.begin());
    while (!rest.empty() && rest.back() == ' ') rest.pop_back();
    return true;
}

int definition_line(const shader_analysis& a, const std::string& name) {
    for (const auto& f : a.functions)
        if (f.name == name) return f.line;
    return 0;
}

// The name in a quoted C++ entity ('normzoo_glsl::library<double>::pow(...)' -> pow), or ""
// where it is the translation's own.
std::string shader_name(const std::string& quoted) {
    std::string q = quoted.substr(0, quoted.find('('));
    while (!q.empty() && (q.back() == ' ' || q.back() == '>')) {
        if (q.back() == '>') {  // a template's arguments
            int depth = 0;
            std::size_t i = q.size();
            while (i-- > 0) {
                depth += q[i] == '>' ? 1 : q[i] == '<' ? -1 : 0;
                if (depth == 0) break;
            }
            q.erase(i == std::string::npos ? 0 : i);
        } else {
            q.pop_back();
        }
    }
    const std::size_t colons = q.rfind("::");
    if (colons != std::string::npos) q = q.substr(colons + 2);
    if (q.rfind("normzoo_id_", 0) == 0) q = q.substr(11);
    if (q == "normzoo_not") q = "not";
    for (char c : q)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return "";
    return q.rfind("normzoo_", 0) == 0 || q.rfind("operator", 0) == 0 ? "" : q;
}

// The text between the first pair of quotes after `from` (GCC's ‘...’ or '...').
std::string quoted_after(const std::string& msg, std::size_t from) {
    for (const char* open : {"\xe2\x80\x98", "'"}) {
        const std::string close = open[0] == '\'' ? "'" : "\xe2\x80\x99";
        const std::size_t b = msg.find(open, from);
        if (b == std::string::npos) continue;
        const std::size_t s = b + std::string(open).size(), e = msg.find(close, s);
        if (e != std::string::npos) return msg.substr(s, e - s);
    }
    return "";
}

// What the compiler's message says, in shading terms.
std::string construct(const std::string& msg) {
    auto has = [&](const char* x) { return msg.find(x) != std::string::npos; };
    const std::string name = shader_name(quoted_after(msg, 0));
    if (has("was not declared") && !name.empty())
        return name + " is no function or variable normzoo knows (its built-in functions are listed in docs/brdf-code.md)";
    if (has("no matching function for call") && !name.empty()) return "no version of " + name + " that normzoo runs takes these arguments";
    if (has("request for member") || has("has no member named")) {
        const std::string member = shader_name(quoted_after(msg, 0));
        return (member.empty() ? std::string("a member") : "." + member) + " is read from a value that has no such field or swizzle";
    }
    if ((has("no match for") || has("invalid operands")) && has("operator")) {
        std::string op;  // up to the closing quote: operator%, operator*=
        for (std::size_t i = msg.rfind("operator") + 8; i < msg.size() && msg[i] != '\'' && static_cast<unsigned char>(msg[i]) < 0x80; ++i)
            op += msg[i];
        for (char c : op)
            if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == ' ') op.clear();
        return "the operator " + op + (op.empty() ? "" : " ") +
               "does not apply to these operands on the CPU (HLSL's * between matrices and % between floats: write mul and fmod)";
    }
    if (has("lvalue") || has("read-only") || has("assignment of"))
        return "an assignment, or an out or inout argument, whose target is not a variable normzoo can write";
    if (has("conversion") || has("convert")) return "a value of one type where normzoo needs another";
    return "a construct normzoo does not run";
}

// Line `line` of the file's code, trimmed, for the message.
std::string code_line(const shader_source& s, int line) {
    std::istringstream in(s.code);
    std::string l;
    for (int k = s.first_line; std::getline(in, l); ++k)
        if (k == line) {
            const std::size_t b = l.find_first_not_of(" \t"), e = l.find_last_not_of(" \t\r");
            if (b == std::string::npos) return "";
            l = l.substr(b, e - b + 1);
            return l.size() > 160 ? l.substr(0, 157) + "..." : l;
        }
    return "";
}

}  // namespace

std::string glslang_message(const std::string& out, const shader_source& s, const shader_analysis& a, int last, int& line) {
    std::istringstream in(out);
    line = 0;
    for (std::string l; std::getline(in, l);) {
        if (l.rfind("ERROR: ", 0) != 0) continue;
        if (l.find("Recursion detected") != std::string::npos) {
            // its next line: "    f(f1; calling g(f1;", functions by their mangled names
            std::string calls;
            std::getline(in, calls);
            const std::size_t at = calls.find(" calling ");
            auto name = [](std::string x) {
                x = x.substr(0, x.find('('));
                const std::size_t b = x.find_first_not_of(" \t");
                return b == std::string::npos ? std::string() : x.substr(b);
            };
            const std::string f = name(calls.substr(0, at)), g = at == std::string::npos ? "" : name(calls.substr(at + 9));
            line = definition_line(a, f);
            return "recursion: " + f + " calls " + g + (f == g ? "" : ", which calls " + f + " again") +
                   ". A shader's functions may not call themselves, directly or through others: GPU compilers refuse it "
                   "(GLSL 4.60, section 6.1; HLSL's compilers alike)";
        }
        const std::size_t colon = l.find(':', 7);
        std::string rest;
        if (colon == std::string::npos || !numbered(l, colon + 1, line, rest)) continue;
        if (line > last) {  // in the main normzoo writes around the code: the BRDF's signature
            line = definition_line(a, s.function);
            return "normzoo cannot call " + s.function + "(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) as written: " + rest;
        }
        return rest;
    }
    return out.substr(0, 400);
}

std::string compiler_message(const std::string& out, const shader_source& s, int& line) {
    std::istringstream in(out);
    line = 0;
    std::string error;
    for (std::string l; std::getline(in, l);) {
        int at = 0;
        std::string rest;
        const bool here = l.rfind(s.path + ":", 0) == 0 && numbered(l, s.path.size() + 1, at, rest);
        if (here && line == 0) line = at;  // the first place in the file: the error's or its "required from here"
        const std::size_t e = l.find("error: ");
        if (e != std::string::npos && error.empty()) error = l.substr(e + 7);
        if (!error.empty() && line != 0) break;
    }
    const std::string code = line > 0 ? code_line(s, line) : "";
    return construct(error) + (code.empty() ? "" : ", in: " + code);
}

}  // namespace verify
