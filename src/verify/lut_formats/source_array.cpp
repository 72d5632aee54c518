// A source file's number array or base64 PNG string (source_array.hpp): the declarations that
// initialise one, found in the file's tokens (source_tokens.hpp); its elements and shape are
// read in source_values.cpp (source_parts.hpp).
#include "source_array.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "../args.hpp"
#include "png.hpp"
#include "source_parts.hpp"
#include "source_tokens.hpp"
#include "texels.hpp"

namespace verify {
namespace {

using tok = source_token;
using kind = source_token::kind;
// Blender's eevee_lut.cc, all of EEVEE's tables, is 2.2 MB; a file of numbers takes about 80
// times its size once read (tokens, numbers, values: 6 MB of "1," took 490 MB)
constexpr std::size_t max_source_bytes = std::size_t(8) << 20;
constexpr std::size_t npos = std::string::npos;

struct parser {
    const std::vector<tok>& t;
    bool open(std::size_t k) const { return k < t.size() && (t[k].is("[") || t[k].is("{") || t[k].is("(")); }
    bool name(std::size_t k) const { return k < t.size() && t[k].what == kind::name; }

    // An array type's constructor, T<...>(, T[N]( or T(: the index of its '(' or npos. A type's
    // brackets are short: scans stop after 16 tokens, so that no input makes every '=' read on
    // to the end of the file.
    std::size_t constructor(std::size_t k) const {
        if (!name(k)) return npos;
        ++k;
        if (k < t.size() && t[k].is("<")) {
            const std::size_t from = k;
            for (int depth = 0; k < t.size() && k < from + 16; ++k) {
                depth += int(t[k].is("<")) - int(t[k].is(">"));
                if (depth == 0 || t[k].is(";")) break;
            }
            if (k >= t.size() || !t[k].is(">")) return npos;
            ++k;
        }
        if (k < t.size() && t[k].is("[")) k += k + 1 < t.size() && t[k + 1].is("]") ? 2 : k + 2 < t.size() && t[k + 2].is("]") ? 3 : t.size();
        return k < t.size() && t[k].is("(") ? k : npos;
    }
    // The elements of the group opening at k, flattened: numbers (a sign before one joined to
    // it), nested groups and constructors (vec2(...)); false for anything else. end: past it.
    bool elements(std::size_t k, found_array& a, std::size_t& end, int depth = 0) const {
        if (depth > 16) return false;
        const char* close = t[k].is("[") ? "]" : t[k].is("{") ? "}" : ")";
        for (++k; k < t.size();) {
            if (t[k].is(close)) return end = k + 1, true;
            char sign = 0;
            if (t[k].is("-") || t[k].is("+")) sign = t[k++].text[0];
            if (k < t.size() && t[k].what == kind::number) {
                a.numbers.push_back({t[k].text, sign, t[k].line}), ++k;
            } else if (!sign && (open(k) || constructor(k) != npos)) {
                if (!elements(open(k) ? k : constructor(k), a, k, depth + 1)) return false;
            } else {
                return false;
            }
            if (k < t.size() && t[k].is(",")) ++k;
            else if (!(k < t.size() && t[k].is(close))) return false;
        }
        return false;
    }
};

// The name a declaration gives before its '=' at k (past declared dimensions and a TypeScript
// annotation), with the dimensions and the element type the declaration names.
std::string declared_name(const std::vector<tok>& t, std::size_t k, found_array& a) {
    std::size_t j = k;
    // [N], [NAME], [] or [expression] groups, read back: at most 4 of at most 32 tokens each
    for (std::size_t groups = 0; j >= 2 && t[j - 1].is("]"); ++groups) {
        std::size_t o = j - 1;
        for (int depth = 0; o-- > 0 && o + 32 > j;) {
            if (t[o].is("]")) ++depth;
            else if (t[o].is("[") && depth-- == 0) break;
        }
        if (o == npos || o + 32 <= j || groups == 4) return "";
        a.dims.insert(a.dims.begin(), o + 3 == j ? std::string(t[o + 1].text) : std::string());  // one token, or unknown
        j = o;
    }
    if (j == 0 || t[j - 1].what != kind::name) return "";
    std::string name(t[j - 1].text);
    if (j >= 3 && t[j - 2].is(":") && t[j - 3].what == kind::name) a.element_type = name, name = std::string(t[j - 3].text), j -= 2;
    static const char* const qualifiers[] = {"const", "static", "constexpr", "let", "var", "export", "inline", "extern"};
    for (std::size_t p = j - 1; a.element_type.empty() && p-- > 0 && p + 4 > j && t[p].what == kind::name;)
        if (std::none_of(std::begin(qualifiers), std::end(qualifiers), [&](const char* q) { return t[p].text == q; }))
            a.element_type = std::string(t[p].text);
    return name;
}

// The type inside an array<T, N>: T's tokens up to the ',' or '>' of the outer brackets.
std::string type_inside(const std::vector<tok>& t, std::size_t lt) {
    std::string type;
    for (std::size_t q = lt + 1, depth = 0; q < t.size(); ++q) {
        if (depth == 0 && (t[q].is(",") || t[q].is(">"))) break;
        depth += t[q].is("<") ? 1 : t[q].is(">") && depth ? std::size_t(-1) : 0;
        type += std::string(t[q].text);
    }
    return type;
}

// The initialiser after the '=' at k: [..] or {..}; new T([..]); T.from([..]); T<..>(..) and
// T[..](..) (WGSL's and GLSL's array constructors); or strings joined by + (or side by side).
// False for any other expression.
bool initialiser(const parser& p, std::size_t k, found_array& a) {
    const auto& t = p.t;
    std::size_t g = k + 1;
    if (g >= t.size()) return false;
    if (t[g].what == kind::string) {
        for (; g < t.size() && t[g].what == kind::string; g += g + 2 < t.size() && t[g + 1].is("+") ? 2 : 1) {
            const std::string_view s = t[g].text;
            if (s.size() < 2 || s.find('\\') != npos || s.find("${") != npos) return false;
            a.text += std::string(s.substr(1, s.size() - 2));
        }
        return a.is_string = true;
    }
    const auto literal = [&](std::size_t q) { return q < t.size() && (t[q].is("[") || t[q].is("{")); };
    if (t[g].text == "new" && p.name(g + 1) && g + 2 < t.size() && t[g + 2].is("(") && literal(g + 3)) {
        a.element_type = std::string(t[g + 1].text), g += 3;
    } else if (p.name(g) && g + 3 < t.size() && t[g + 1].is(".") && t[g + 2].text == "from" && t[g + 3].is("(") && literal(g + 4)) {
        a.element_type = std::string(t[g].text), g += 4;
    } else if (p.name(g) && g + 1 < t.size() && (t[g + 1].is("<") || t[g + 1].is("["))) {
        const std::size_t paren = p.constructor(g);
        if (paren == npos) return false;
        a.element_type = t[g + 1].is("<") ? type_inside(t, g + 1) : std::string(t[g].text);
        g = paren;
    } else if (!literal(g)) {
        return false;
    }
    std::size_t end = 0;
    return p.elements(g, a, end) && !a.numbers.empty();
}

bool c_like(const std::string& path) {
    std::string ext = path.substr(std::min(path.size(), path.find_last_of('.')));
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext != ".js" && ext != ".ts" && ext != ".wgsl";
}

// The first declaration that initialises an array (or a base64 PNG string), or the one named.
std::optional<found_array> find_array(const std::string& path, const std::vector<tok>& t, const array_request& request) {
    const parser p{t};
    for (std::size_t k = 1; k < t.size(); ++k) {
        if (!t[k].is("=")) continue;
        found_array a;
        a.line = t[k].line;
        a.name = declared_name(t, k, a);
        if (!request.name.empty() && a.name != request.name) continue;
        if (!initialiser(p, k, a)) {
            if (!request.name.empty())
                throw bad_input(path + ":" + std::to_string(a.line) + ": '" + a.name +
                                "' is not initialised by an array of numbers nor by a base64 PNG string");
            continue;
        }
        if (a.is_string && !base64_png(a.text) && request.name.empty()) continue;
        return a;
    }
    return std::nullopt;
}

// A file that is a list of numbers alone, comma-separated (what an initialiser's #include holds:
// openpbr-bsdf's impl/data/*_data.h), as an unnamed array; nullopt for anything else.
std::optional<found_array> bare_list(const std::vector<tok>& t) {
    found_array a;
    for (std::size_t k = 0; k < t.size();) {
        char sign = 0;
        if (t[k].is("-") || t[k].is("+")) sign = t[k++].text[0];
        if (!(k < t.size() && t[k].what == kind::number)) return std::nullopt;
        if (a.numbers.empty()) a.line = t[k].line;
        a.numbers.push_back({t[k].text, sign, t[k].line}), ++k;
        if (k < t.size() && !t[k++].is(",")) return std::nullopt;
    }
    if (a.numbers.empty()) return std::nullopt;
    return a;
}

}  // namespace

bool is_source_file_name(const std::string& path) {
    const std::size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
    if (dot == npos || (slash != npos && dot < slash)) return false;
    std::string ext = path.substr(dot);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const char* e : {".h", ".hpp", ".inc", ".c", ".cpp", ".js", ".ts", ".wgsl", ".glsl"})
        if (ext == e) return true;
    return false;
}

decoded_lut read_source_array(const std::string& path, const std::string& text, const array_request& request) {
    if (text.size() > max_source_bytes)
        throw bad_input(path + ": a source file of " + std::to_string(text.size()) + " bytes; a table's is at most 8 MiB");
    const std::vector<tok> t = tokenize_source(path, text, c_like(path));
    std::optional<found_array> a = find_array(path, t, request);
    if (!a && request.name.empty()) a = bare_list(t);
    if (!a)
        throw bad_input(path + ": " + (request.name.empty() ? "no declaration initialises an array of numbers or a base64 PNG string"
                                                            : "nothing named '" + request.name + "' is initialised"));
    if (a->is_string) {
        const std::optional<std::string> png = base64_png(a->text);
        const std::string where = path + ":" + std::to_string(a->line);
        if (!png) throw bad_input(where + ": the string '" + a->name + "' is not a PNG in base64 (plain or a data: URI)");
        decoded_lut d = read_png(where + ": the base64 PNG '" + a->name + "'", *png);
        d.format = "base64-" + d.format;
        d.array_name = a->name, d.shape_from = "the PNG's own size";
        return d;
    }
    return array_values(path, t, *a, request);
}

void interpret_hex(const std::string& path, decoded_lut& d, hex_meaning m) {
    if (d.encoding != value_encoding::hex_integer) throw bad_input(path + ": the array '" + d.array_name + "' holds no hex integers");
    const double most = m == hex_meaning::unorm8 ? 0xff : 0xffff;
    for (double& v : d.image.data) {
        if (v > most)
            throw bad_input(path + ": the array '" + d.array_name + "' holds " + std::to_string(std::uint64_t(v)) + ", more than " +
                            (m == hex_meaning::unorm8 ? "an 8-bit" : "a 16-bit") + " integer holds");
        v = m == hex_meaning::binary16 ? half_to_double(std::uint16_t(v)) : v / most;
    }
    d.precision.clear();
    set_storage_tolerance(d, m == hex_meaning::binary16 ? value_encoding::half
                             : m == hex_meaning::unorm8 ? value_encoding::unorm8 : value_encoding::unorm16);
}

}  // namespace verify
