#include "citations.hpp"

#include <cstdlib>
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
    // Parsed by hand: the markers are fixed strings (std::regex is slow and trips GCC 12's
    // -Wmaybe-uninitialized under the sanitizers).
    static const std::string open = "<!-- normzoo:cite ", open_end = " -->\n", close = "<!-- /normzoo:cite -->";
    std::string out;
    std::size_t pos = 0;
    for (std::size_t start; (start = text.find(open, pos)) != std::string::npos;) {
        const std::size_t head_end = text.find(open_end, start);
        if (head_end == std::string::npos) break;
        std::istringstream head(text.substr(start + open.size(), head_end - start - open.size()));
        std::string name, rows_text;
        head >> name >> rows_text;
        int rows = 0;
        if (rows_text.rfind("rows=", 0) == 0) rows = std::atoi(rows_text.c_str() + 5);
        const std::size_t body_start = head_end + open_end.size();
        const std::size_t end = text.find(close, body_start);
        if (end == std::string::npos) {
            stale.push_back(file + ": a citation of " + name + " is not closed by " + close);
            break;
        }
        out += text.substr(pos, body_start - pos);
        const std::string current = text.substr(body_start, end - body_start);
        const auto it = markdown_by_name.find(name);
        if (it == markdown_by_name.end()) {
            out += current;
        } else {
            const std::string fresh = cited_body(it->second, name, rows);
            if (fresh != current) stale.push_back(file + ": the citation of " + name + " differs from the table the code produces");
            out += fresh;
        }
        pos = end;
    }
    out += text.substr(pos);
    return out;
}

}  // namespace verify
