// Docs that cite tables: blocks between
//     <!-- normzoo:cite NAME.md -->  (or  <!-- normzoo:cite NAME.md rows=K from=X columns=a,b,c -->)
//     <!-- /normzoo:cite -->
// hold the Markdown table of results/NAME.md (its first K rows from the first whose first cell
// is X, the named columns) and where it came from. A run
// that writes the tables refreshes them; --check fails when one differs from what the code
// produces, so a cited number cannot go stale.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace verify {

// `text` with every block whose table is in `markdown_by_name` (NAME.md -> its Markdown)
// brought up to date; a note per block that was not already current goes to `stale`.
std::string refresh_citations(const std::string& text, const std::map<std::string, std::string>& markdown_by_name,
                              const std::string& file, std::vector<std::string>& stale);

}  // namespace verify
