#include "citations.hpp"

#include <regex>
#include <sstream>

namespace verify {

namespace {

// The provenance line and the table lines of a results file, the first `rows` data rows only
// when rows > 0.
std::string cited_body(const std::string& markdown, const std::string& name, int rows) {
    std::istringstream in(markdown);
    std::string line, produced, table;
    int data = 0, table_lines = 0;
    while (std::getline(in, line)) {
        if (line.rfind("Produced by ", 0) == 0) produced = line;
        if (line.rfind("|", 0) != 0) {
            if (table_lines > 0) break;  // the first table only
            continue;
        }
        ++table_lines;
        if (table_lines > 2 && rows > 0 && data++ >= rows) continue;
        table += line + "\n";
    }
    std::string body = "From [`results/" + name + "`](../results/" + name + "): " +
                       (produced.empty() ? std::string("normzoo") : produced.substr(std::string("Produced by ").size())) +
                       "\n\n" + table;
    return body;
}

}  // namespace

std::string refresh_citations(const std::string& text, const std::map<std::string, std::string>& markdown_by_name,
                              const std::string& file, std::vector<std::string>& stale) {
    static const std::regex open(R"(<!-- normzoo:cite ([A-Za-z0-9_.-]+\.md)(?: rows=([0-9]+))? -->\n)");
    static const std::string close = "<!-- /normzoo:cite -->";
    std::string out;
    std::size_t pos = 0;
    std::smatch m;
    auto begin = text.cbegin();
    while (std::regex_search(begin + static_cast<std::ptrdiff_t>(pos), text.cend(), m, open)) {
        const std::size_t start = pos + static_cast<std::size_t>(m.position(0));
        const std::size_t body_start = start + static_cast<std::size_t>(m.length(0));
        const std::size_t end = text.find(close, body_start);
        if (end == std::string::npos) {
            stale.push_back(file + ": a citation of " + m[1].str() + " is not closed by " + close);
            break;
        }
        out += text.substr(pos, body_start - pos);
        const std::string name = m[1].str();
        const auto it = markdown_by_name.find(name);
        const std::string current = text.substr(body_start, end - body_start);
        if (it == markdown_by_name.end()) {
            out += current;
        } else {
            const std::string fresh = cited_body(it->second, name, m[2].matched ? std::stoi(m[2].str()) : 0);
            if (fresh != current) stale.push_back(file + ": the citation of " + name + " differs from the table the code produces");
            out += fresh;
        }
        pos = end;
    }
    out += text.substr(pos);
    return out;
}

}  // namespace verify
