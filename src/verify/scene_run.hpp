// Runs what a scene needs and nothing else: the plan for `./verify --scene FILE`.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "scene.hpp"
#include "writers.hpp"

namespace verify {

struct skipped_table {
    std::string table, reason;
};

std::vector<table_output> scene_tables(const scene& s, unsigned jobs, std::vector<skipped_table>& skipped);

}  // namespace verify
