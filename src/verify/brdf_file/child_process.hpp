// The external programs a shader file goes through (the preprocessor, glslangValidator, the C++
// compiler), each run as a child process under caps on its time, its memory and what it prints,
// so that no file can make a step run for minutes or take the machine's memory
// (docs/brdf-code.md#safety). No shell: the arguments go to the program as given.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace verify {

// The caps of each step, from the environment (docs/brdf-code.md#caps): bad values are bad_input
// naming the variable.
struct shader_caps {
    double seconds = 10;                       // NORMZOO_SHADER_SECONDS: preprocessing, validation
    std::size_t memory_mb = 2048;              // NORMZOO_SHADER_MEMORY_MB: every step's address space
    std::size_t text_mb = 8;                   // NORMZOO_SHADER_TEXT_MB: the code read, and the preprocessed text
    std::size_t text_bytes() const { return text_mb << 20; }
};
shader_caps shader_caps_from_environment();

struct child_limits {
    double seconds = 10;
    std::size_t memory_bytes = std::size_t(2048) << 20;  // RLIMIT_AS of the child (and of what it starts)
    std::size_t output_bytes = std::size_t(8) << 20;     // its standard output; its standard error keeps 64 KiB
};

struct child_result {
    enum class ending { exited, signaled, timed_out, output_capped, not_started } how = ending::exited;
    int status = 0;   // the exit status, or the signal
    std::string out, err;
    // It stopped for want of memory (under its cap, what the program itself says).
    bool out_of_memory() const;
    bool ok() const { return how == ending::exited && status == 0; }
};

// Runs argv[0] (found on PATH) with argv in `cwd` (empty: this process's), standard input empty,
// LC_ALL=C; stops it (and whatever it started) at the time or output cap.
child_result run_child(const std::vector<std::string>& argv, const child_limits& limits, const std::string& cwd = "");

// Why a step's child failed, in words, or "" when it ran to its end: "took longer than 10 s
// (NORMZOO_SHADER_SECONDS)", "ran out of memory under its memory cap of 2048 MB (NORMZOO_SHADER_MEMORY_MB)", ...
std::string cap_tripped(const child_result& r, const child_limits& limits, const char* seconds_variable);

}  // namespace verify
