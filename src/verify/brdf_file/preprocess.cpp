#include "preprocess.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "../args.hpp"
#include "shader_screen.hpp"
#include "wgsl.hpp"

namespace verify {

namespace fs = std::filesystem;

namespace {

// A folder of its own for one run's copies, removed with it; the preprocessor runs in its empty
// subfolder `cwd`, so that a name it resolves by itself finds nothing.
struct work_dir {
    fs::path path;
    work_dir() {
        std::string t = (fs::temp_directory_path() / "normzoo-pp-XXXXXX").string();
        if (!::mkdtemp(t.data())) throw bad_input("cannot create a temporary folder in " + fs::temp_directory_path().string());
        path = t;
        fs::create_directory(path / "cwd");
    }
    ~work_dir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    work_dir(const work_dir&) = delete;
    work_dir& operator=(const work_dir&) = delete;
};

bool inside(const fs::path& p, const fs::path& root) {
    auto r = root.begin();
    for (auto q = p.begin(); r != root.end(); ++r, ++q)
        if (q == p.end() || *q != *r) return false;
    return true;
}

std::string trimmed(const std::string& s) {
    const std::size_t a = s.find_first_not_of(" \t");
    return a == std::string::npos ? "" : s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

std::vector<std::string> words_of(const std::string& s) {
    std::istringstream in(s);
    std::vector<std::string> w;
    for (std::string x; in >> x;) w.push_back(x);
    return w;
}

// The file and the files it includes, each read once and screened, written to `work` as the copy
// the preprocessor reads, its #include directives naming the copies. An include that leaves the
// folders, is not found or is refused names a file that does not exist (refused-K): the
// preprocessor fails on it only where the include is active, and the message is refusals[K].
class include_graph {
public:
    include_graph(const shader_source& raw, const preprocess_options& o, const shader_caps& caps, const fs::path& work)
        : caps_(caps), work_(work), hlsl_(raw.lang == shader_source::language::hlsl) {
        const fs::path file = fs::weakly_canonical(fs::absolute(raw.path));
        own_dir_ = file.parent_path();
        roots_.push_back(own_dir_);
        for (const auto& d : o.include_dirs) {
            std::error_code ec;
            const fs::path c = fs::canonical(d, ec);
            if (ec || !fs::is_directory(c)) throw bad_input("--include-dir " + d + ": not a folder");
            dirs_.push_back({c, d});
            roots_.push_back(c);
        }
        const std::string shown_dir = fs::path(raw.path).parent_path().string();
        shown_own_dir_ = shown_dir.empty() ? "." : shown_dir;
        files_.push_back({file, raw.path});
        index_[file] = 0;
        count(raw.path, raw.code.size());
        prepare(0, std::string(static_cast<std::size_t>(std::max(0, raw.first_line - 1)), '\n') + raw.code);
        for (std::size_t k = 1; k < files_.size(); ++k) prepare_included(k);
    }
    fs::path copy(std::size_t k) const { return work_ / std::to_string(k); }
    // The file a copy's path stands for, or "" for none of them.
    std::string shown_of(const std::string& copy_path) const {
        const std::string prefix = (work_ / "").string();
        if (copy_path.size() <= prefix.size() || copy_path.compare(0, prefix.size(), prefix) != 0) return "";
        const std::string k = copy_path.substr(prefix.size());
        if (k.size() > 9 || !std::all_of(k.begin(), k.end(), ::isdigit) || (k.size() > 1 && k[0] == '0')) return "";
        const std::size_t i = std::stoul(k);
        return i < files_.size() ? files_[i].shown : "";
    }
    const std::string& refusal_of(const std::string& copy_path) const {
        static const std::string none;
        const std::string prefix = (work_ / "refused-").string();
        if (copy_path.rfind(prefix, 0) != 0) return none;
        const std::size_t k = std::strtoul(copy_path.c_str() + prefix.size(), nullptr, 10);
        return k < refusals_.size() ? refusals_[k] : none;
    }
    const std::string& version() const { return version_; }

private:
    struct file {
        fs::path canonical;
        std::string shown;
    };
    struct folder {
        fs::path canonical;
        std::string shown;
    };

    void prepare_included(std::size_t k) {
        std::ifstream in(files_[k].canonical, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        const std::string t = text.str();
        count(files_[k].shown, t.size());
        try {
            if (!in || t.find('\0') != std::string::npos) throw bad_input(files_[k].shown + ": not a text file");
            prepare(k, t);
        } catch (const bad_input& e) {  // refused where it is included, if that include is active
            std::ofstream(copy(k)) << "#include \"" << refused(e.what()) << "\"\n";
        }
    }

    // The code read so far, the checked file's and its includes', against the cap.
    void count(const std::string& shown, std::size_t bytes) {
        read_ += bytes;
        if (read_ > caps_.text_bytes())
            throw bad_input(shown + ": the code and the files it includes exceed the cap of " + std::to_string(caps_.text_mb) +
                            " MB (NORMZOO_SHADER_TEXT_MB)");
    }

    std::string refused(const std::string& message) {
        refusals_.push_back(message);
        return (work_ / ("refused-" + std::to_string(refusals_.size() - 1))).string();
    }

    // The screened copy of file k: includes name the copies, #pragma once stays, other pragmas go
    // (mcpp's own among them), #version is read off the file, #extension becomes a pragma the
    // output keeps where it is active.
    void prepare(std::size_t k, const std::string& text) {
        screened_text s = screen_input(files_[k].shown, text, hlsl_);
        std::vector<std::string> with;  // each directive's text in the copy, in the file's order
        for (const auto& d : s.directives) {
            const std::string rest = trimmed(d.rest);
            with.push_back(s.text.substr(d.begin, d.end - d.begin));
            if (d.name == "include") with.back() = "#include \"" + include(k, rest, d.line) + "\"";
            else if (d.name == "pragma") with.back() = words_of(rest) == std::vector<std::string>{"once"} ? "#pragma once" : "";
            else if (d.name == "version") with.back() = "", read_version(k, rest, d.line);
            else if (d.name == "extension") with.back() = "#pragma extension " + extension(k, rest, d.line);
        }
        for (std::size_t i = s.directives.size(); i-- > 0;)
            s.text.replace(s.directives[i].begin, s.directives[i].end - s.directives[i].begin, with[i]);
        std::ofstream(copy(k), std::ios::binary) << s.text;
    }

    void read_version(std::size_t k, const std::string& rest, int line) {
        // the versions glslang validates (glslangValidator --glsl-version lists them)
        static const std::set<std::string> known{"100",    "110",    "120",    "130", "140", "150", "300 es", "310 es", "320 es",
                                                 "330",    "400",    "410",    "420", "430", "440", "450", "460"};
        const auto w = words_of(rest);
        const bool profile = w.size() == 2 && (w[1] == "core" || w[1] == "compatibility") && w[0] >= "150" && known.count(w[0]);
        if (!(w.size() == 1 && known.count(w[0])) && !(w.size() == 2 && known.count(w[0] + " " + w[1])) && !profile)
            throw bad_input(files_[k].shown + ":" + std::to_string(line) + ": '#version " + rest +
                            "' is not a version glslang validates (110 to 460, 100, 300 es, 310 es, 320 es)");
        if (k == 0 && version_.empty()) version_ = w.size() == 2 ? w[0] + " " + w[1] : w[0];
    }

    std::string extension(std::size_t k, const std::string& rest, int line) const {
        const std::size_t colon = rest.find(':');
        const std::string name = trimmed(rest.substr(0, colon)), behavior = colon == std::string::npos ? "" : trimmed(rest.substr(colon + 1));
        const bool ok = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }) &&
                        (behavior == "require" || behavior == "enable" || behavior == "warn" || behavior == "disable");
        if (!ok) throw bad_input(files_[k].shown + ":" + std::to_string(line) + ": '#extension " + rest + "': #extension NAME : require, enable, warn or disable");
        return name + " : " + behavior;
    }

    std::string folders() const {
        std::string f = shown_own_dir_;
        for (const auto& d : dirs_) f += ", " + d.shown;
        return f;
    }

    // The copy an #include of file k at `line` names: "NAME" from k's folder, then the include
    // folders, then the file's own; <NAME> the same without k's folder.
    std::string include(std::size_t k, const std::string& header, int line) {
        const std::string at = files_[k].shown + ":" + std::to_string(line) + ": #include " + header;
        const bool quoted = header.size() >= 2 && header.front() == '"' && header.back() == '"';
        const bool angled = header.size() >= 2 && header.front() == '<' && header.back() == '>';
        if (!quoted && !angled) throw bad_input(at + ": #include takes \"FILE\" or <FILE> (a macro is not followed)");
        const std::string name = header.substr(1, header.size() - 2);
        if (name.empty()) throw bad_input(at + ": no file named");
        std::vector<std::pair<fs::path, fs::path>> tries;  // the candidate, and how messages name it
        if (fs::path(name).is_absolute()) {
            tries.push_back({name, name});
        } else {
            if (quoted) tries.push_back({files_[k].canonical.parent_path() / name, fs::path(files_[k].shown).parent_path() / name});
            for (const auto& d : dirs_) tries.push_back({d.canonical / name, fs::path(d.shown) / name});
            tries.push_back({own_dir_ / name, fs::path(shown_own_dir_) / name});
        }
        for (const auto& [candidate, shown] : tries) {
            std::error_code ec;
            if (!fs::exists(candidate, ec)) continue;
            const fs::path real = fs::canonical(candidate, ec);
            if (ec || !std::any_of(roots_.begin(), roots_.end(), [&](const fs::path& r) { return inside(real, r); }))
                return refused(at + " leaves the include folders (" + folders() + "): it is " + real.string() +
                               "; --include-dir adds a folder (docs/brdf-code.md#the-preprocessor)");
            if (!fs::is_regular_file(real, ec)) return refused(at + ": " + shown.lexically_normal().string() + " is not a file");
            auto found = index_.find(real);
            if (found == index_.end()) {
                found = index_.emplace(real, files_.size()).first;
                files_.push_back({real, shown.lexically_normal().string()});
            }
            return copy(found->second).string();
        }
        return refused(at + " is not found in the include folders (" + folders() + "; docs/brdf-code.md#the-preprocessor)");
    }

    const shader_caps& caps_;
    fs::path work_;
    bool hlsl_;
    fs::path own_dir_;
    std::string shown_own_dir_;
    std::vector<folder> dirs_;
    std::vector<fs::path> roots_;
    std::vector<file> files_;
    std::map<fs::path, std::size_t> index_;
    std::vector<std::string> refusals_;
    std::size_t read_ = 0;
    std::string version_;
};

// The macros GLSL's compilers define (GLSL 4.60 and GLSL ES 3.00, "Preprocessor"): __VERSION__,
// and GL_ES and GL_FRAGMENT_PRECISION_HIGH in the ES profiles. Without #version, the version
// validation checks against. HLSL's compilers' own are not made.
std::vector<std::string> predefined(const std::string& version, bool hlsl) {
    if (hlsl) return {};
    const std::string number = version.empty() ? "120" : version.substr(0, 3);
    std::vector<std::string> d{"-D__VERSION__=" + number};
    if (number == "100" || version.find(" es") != std::string::npos) d.insert(d.end(), {"-DGL_ES=1", "-DGL_FRAGMENT_PRECISION_HIGH=1"});
    return d;
}

// mcpp's first error, "FILE:LINE: error: MESSAGE" (or a fatal one) about one of the copies, as
// the file's name and line; in GLSL also a macro redefined with another body, which GLSL's
// compilers refuse where C's warn. An include that was refused: its own message.
std::string first_error(const std::string& err, const include_graph& g, bool hlsl, const std::string& work) {
    std::istringstream in(err);
    for (std::string l; std::getline(in, l);) {
        l = trimmed(l);
        for (const std::string kind : {": error: ", ": fatal error: ", ": warning: "}) {
            const std::size_t at = l.find(kind);
            if (at == std::string::npos || (kind == ": warning: " && (hlsl || l.find("The macro is redefined") == std::string::npos))) continue;
            const std::size_t colon = l.rfind(':', at - 1);
            if (colon == std::string::npos) continue;
            const std::string shown = g.shown_of(l.substr(0, colon));
            if (shown.empty()) continue;
            std::string message = l.substr(at + kind.size());
            const std::string cannot_open = "Can't open include file \"";
            if (const std::size_t q = message.find(cannot_open); q != std::string::npos) {
                const std::size_t from = q + cannot_open.size();
                const std::string& refusal = g.refusal_of(message.substr(from, message.find('"', from) - from));
                if (!refusal.empty()) return refusal;
            }
            for (std::size_t p = message.find(work); p != std::string::npos; p = message.find(work, p + 1)) {
                std::size_t e = p + work.size();
                while (e < message.size() && message[e] != '"' && message[e] != ' ' && message[e] != ':') ++e;
                const std::string name = g.shown_of(message.substr(p, e - p));
                message.replace(p, e - p, name.empty() ? "?" : name);
            }
            if (message.find("Buffer overflow") != std::string::npos || message.find("Too long") != std::string::npos)
                message += " (a macro's expansion exceeds what the preprocessor holds)";
            return shown + ":" + l.substr(colon + 1, at - colon - 1) + ": preprocessor error: " + message;
        }
    }
    return "";
}

struct code_lines {
    std::string code;
    std::vector<code_origin> origin;
    std::vector<std::string> extensions;
};

// The preprocessor's output: its #line markers (which must name the copies) become each line's
// origin, the #extension pragmas the active extensions; every other line is screened code.
code_lines read_output(const std::string& out, const include_graph& g, const std::string& path) {
    code_lines c;
    std::string shown = path;
    int line = 1;
    std::istringstream in(out);
    for (std::string l; std::getline(in, l);) {
        if (l.rfind("#line ", 0) == 0) {
            const std::size_t q = l.find('"');
            line = std::atoi(l.c_str() + 6);
            if (q != std::string::npos) {
                const std::string file = l.substr(q + 1, l.rfind('"') - q - 1);
                shown = g.shown_of(file);
                if (shown.empty()) throw bad_input(path + ": the preprocessor read " + file + ", which is not among the files it was given");
            }
            continue;
        }
        const std::string t = trimmed(l);
        if (t.rfind("#pragma extension ", 0) == 0) {
            const std::string e = t.substr(18);
            if (std::find(c.extensions.begin(), c.extensions.end(), e) == c.extensions.end()) c.extensions.push_back(e);
            l.clear();
        }
        screen_output_line(l, shown + ":" + std::to_string(line));
        c.code += l + "\n";
        c.origin.push_back({shown, line++});
    }
    return c;
}

bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The next word of code at or after `i`, skipping blanks and newlines; `i` moves past it.
std::string next_word(const std::string& code, std::size_t& i) {
    while (i < code.size() && std::isspace(static_cast<unsigned char>(code[i]))) ++i;
    const std::size_t from = i;
    while (i < code.size() && is_word(code[i])) ++i;
    return code.substr(from, i - from);
}

// GLSL's `precision Q TYPE;` statements, made blanks (their newlines kept): the translation has no
// precision and validation sets its own. Returns the Q of the last one for float.
std::string drop_precision_statements(std::string& code) {
    std::string float_precision;
    for (std::size_t at = code.find("precision"); at != std::string::npos; at = code.find("precision", at + 9)) {
        if ((at > 0 && is_word(code[at - 1])) || (at + 9 < code.size() && is_word(code[at + 9]))) continue;
        std::size_t i = at + 9;
        const std::string q = next_word(code, i), type = next_word(code, i);
        while (i < code.size() && std::isspace(static_cast<unsigned char>(code[i]))) ++i;
        if ((q != "lowp" && q != "mediump" && q != "highp") || type.empty() || i >= code.size() || code[i] != ';') continue;
        for (std::size_t j = at; j <= i; ++j)
            if (code[j] != '\n') code[j] = ' ';
        if (type == "float") float_precision = q;
    }
    return float_precision;
}

// WGSL has no preprocessor: its translator (wgsl.hpp) takes the preprocessor's place, and what
// comes out is plain GLSL, on the file's own lines.
shader_source translated_wgsl(const shader_source& raw, const preprocess_options& options, const shader_caps& caps) {
    if (!options.defines.empty() || !options.include_dirs.empty())
        throw bad_input(raw.path + ": --define and --include-dir have no meaning for WGSL, which has no preprocessor (docs/brdf-code.md#wgsl)");
    if (raw.code.size() > caps.text_bytes())
        throw bad_input(raw.path + ": the code exceeds the cap of " + std::to_string(caps.text_mb) + " MB (NORMZOO_SHADER_TEXT_MB)");
    shader_source s = raw;
    translate_wgsl(s, caps.memory_mb << 20);
    if (s.code.size() > caps.text_bytes())  // what the later steps read, as the preprocessed text of any file
        throw bad_input(raw.path + ": its translation to GLSL exceeds the cap of " + std::to_string(caps.text_mb) + " MB (NORMZOO_SHADER_TEXT_MB)");
    s.preprocessed = true;
    return s;
}

}  // namespace

shader_source preprocess_shader(const shader_source& raw, const preprocess_options& options, const shader_caps& caps) {
    if (raw.lang == shader_source::language::wgsl) return translated_wgsl(raw, options, caps);
    for (const auto& d : options.defines) check_define(d);
    const bool hlsl = raw.lang == shader_source::language::hlsl;
    const work_dir work;
    const include_graph g(raw, options, caps, work.path);
    std::vector<std::string> argv{"mcpp", "-I-", "-N", "-k"};
    for (const auto& d : predefined(g.version(), hlsl)) argv.push_back(d);
    for (const auto& d : options.defines) argv.push_back("-D" + d);
    argv.push_back(g.copy(0).string());
    const child_limits limits{caps.seconds, caps.memory_mb << 20, caps.text_bytes()};
    const child_result r = run_child(argv, limits, (work.path / "cwd").string());
    if (r.how == child_result::ending::not_started || (r.how == child_result::ending::exited && r.status == 127))
        throw bad_input(raw.path + ": mcpp, the preprocessor, did not start (tools/install-deps installs it)");
    const std::string cap = cap_tripped(r, limits, "NORMZOO_SHADER_SECONDS");
    if (!cap.empty()) throw bad_input(raw.path + ": preprocessing stopped: it " + cap);
    const std::string error = first_error(r.err, g, hlsl, work.path.string() + "/");
    if (!error.empty()) throw bad_input(error);
    if (!r.ok()) throw bad_input(raw.path + ": the preprocessor failed: " + r.err.substr(0, r.err.find('\n')));
    code_lines c = read_output(r.out, g, raw.path);
    shader_source s = raw;
    s.code = std::move(c.code);
    s.origin = std::move(c.origin);
    s.extensions = std::move(c.extensions);
    s.first_line = 1;
    s.preprocessed = true;
    s.version = g.version();
    if (!hlsl) s.float_precision = drop_precision_statements(s.code);
    return s;
}

shader_source read_preprocessed(const std::string& path, const preprocess_options& options) {
    return preprocess_shader(read_shader_file(path), options, shader_caps_from_environment());
}

}  // namespace verify
