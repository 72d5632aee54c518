#include "citations.hpp"

#include <cstdlib>
#include <sstream>

namespace verify {

namespace {

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream in(text);
    while (std::getline(in, part, sep)) parts.push_back(part);
    return parts;
}

// A table line keeping only the cells at `keep` (indices into its cells).
std::string keep_cells(const std::string& line, const std::vector<std::size_t>& keep) {
    const auto cells = split(line, '|');  // cells[0] is the empty text before the first '|'
    std::string out = "|";
    for (std::size_t k : keep) out += (k + 1 < cells.size() ? cells[k + 1] : std::string()) + "|";
    return out;
}

// The provenance line and the table lines of a results file, the first `rows` data rows only
// when rows > 0, from the first data row whose first cell is `from` when it is not empty (e.g.
// one form's rows of a table of all forms), and only the named columns when `columns` is not
// empty (e.g. to leave out timings, which differ from run to run).
std::string cited_body(const std::string& markdown, const std::string& name, int rows, const std::string& from,
                       const std::vector<std::string>& columns) {
    std::istringstream in(markdown);
    std::string line, produced, table;
    int data = 0, table_lines = 0;
    bool started = from.empty();
    std::vector<std::size_t> keep;
    while (std::getline(in, line)) {
        if (line.rfind("Produced by ", 0) == 0) produced = line;
        if (line.rfind("|", 0) != 0) {
            if (table_lines > 0) break;  // the first table only
            continue;
        }
        ++table_lines;
        if (table_lines == 1 && !columns.empty()) {
            const auto head = split(line, '|');
            for (const auto& c : columns)
                for (std::size_t i = 1; i < head.size(); ++i)
                    if (head[i] == " " + c + " ") keep.push_back(i - 1);
        }
        if (table_lines > 2 && !started) {
            const auto cells = split(line, '|');
            started = cells.size() > 1 && cells[1] == " " + from + " ";
            if (!started) continue;
        }
        if (table_lines > 2 && rows > 0 && data++ >= rows) continue;
        table += (keep.empty() ? line : keep_cells(line, keep)) + "\n";
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
        std::string name, option;
        head >> name;
        int rows = 0;
        std::string from;
        std::vector<std::string> columns;
        while (head >> option) {
            if (option.rfind("rows=", 0) == 0) rows = std::atoi(option.c_str() + 5);
            if (option.rfind("from=", 0) == 0) from = option.substr(5);
            if (option.rfind("columns=", 0) == 0) columns = split(option.substr(8), ',');
        }
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
            const std::string fresh = cited_body(it->second, name, rows, from, columns);
            if (fresh != current) stale.push_back(file + ": the citation of " + name + " differs from the table the code produces");
            out += fresh;
        }
        pos = end;
    }
    out += text.substr(pos);
    return out;
}

}  // namespace verify
