// lut: the tables engines bake, exact, or an engine's own table checked against them
// (docs/lut.md). Named only; it reads options of its own (lut.hpp), and writes only to --out.
#include "../table_spec.hpp"

#include "../lut.hpp"

namespace verify {

namespace {

// Every option lut reads: what to make (or check), and how to write it.
std::vector<std::string> lut_reads() {
    std::vector<std::string> reads = {"--kind", "--model", "--size", "--alpha", "--r", "--mu", "--f0"};
    for (const auto& q : part_parameters()) reads.push_back(std::string("--") + q.name);
    for (const char* o : {"--map", "--format", "--check", "--tolerance", "--monte-carlo", "--layout", "--preset", "--detect"}) reads.emplace_back(o);
    return reads;
}

}  // namespace

table_spec lut_spec() {
    table_spec s{"lut",
                 "the tables engines bake (split-sum pair, E, E_avg), exact, or an engine's own table checked "
                 "(lut --check FILE; docs/lut.md)",
                 lut_reads(),
                 lut_tables,
                 false,
                 "texels"};
    s.check_options = check_lut_options;
    s.writes_by_default = false;
    return s;
}

}  // namespace verify
