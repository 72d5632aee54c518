// Values that are options, refused (option_values.hpp).
#include "option_values.hpp"

#include <CLI/CLI.hpp>

#include "args.hpp"

namespace verify {

namespace {

// Options whose value is a path: one that begins with '-' can be written ./-name.
bool takes_path(const std::string& name) {
    return name == "--out" || name == "--junit" || name == "--scene" || name == "--check" || name == "--brdf";
}

// The error for option `name` followed by `value`, an option rather than its value.
bad_input missing_value(const std::string& prefix, const std::string& name, const std::string& value) {
    return bad_input(prefix + name + ": missing its value ('" + value + "' is an option, not a value" +
                     (takes_path(name) ? "; a path that begins with '-' can be written ./" + value : std::string()) + ")");
}

}  // namespace

std::set<std::string> option_names(const CLI::App& app) {
    std::set<std::string> names;
    for (const CLI::Option* opt : app.get_options()) {
        for (const auto& n : opt->get_lnames()) names.insert("--" + n);
        for (const auto& n : opt->get_snames()) names.insert("-" + n);
    }
    return names;
}

bool option_like(const std::string& value, const std::set<std::string>& names) {
    return value.rfind("--", 0) == 0 || names.count(value);
}

void refuse_missing_values(const CLI::App& app, int argc, const char* const* argv, const std::string& prefix,
                           const std::set<std::string>& also) {
    const std::set<std::string> names = option_names(app);
    std::set<std::string> taking_values = also;
    for (const CLI::Option* opt : app.get_options())
        if (opt->get_items_expected_min() > 0)  // not a flag
            for (const auto& n : opt->get_lnames()) taking_values.insert("--" + n);
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (!taking_values.count(a)) continue;
        if (i + 1 == argc) throw bad_input(prefix + a + ": missing its value (nothing follows it)");
        const std::string next = argv[i + 1];
        if (option_like(next, names)) throw missing_value(prefix, a, next);
        ++i;
    }
}

void refuse_forgotten_values(const CLI::App& app, const std::string& prefix) {
    const std::set<std::string> names = option_names(app);
    for (const CLI::Option* opt : app.get_options()) {
        if (opt->get_positional() || opt->get_lnames().empty()) continue;
        const std::string name = "--" + opt->get_lnames().front();
        for (const auto& value : opt->results()) {
            if (option_like(value, names)) throw missing_value(prefix, name, value);
            // an empty path would silently mean "none" (every table, no JUnit, the default folder)
            if (takes_path(name) && value.empty()) throw bad_input(prefix + name + ": the path is empty");
        }
    }
}

}  // namespace verify
