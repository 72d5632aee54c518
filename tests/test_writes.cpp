// Nothing lost: a run killed by SIGINT or SIGTERM at any moment leaves its output folder exactly
// as it was or (killed while renaming) holding its complete new set; two runs writing the same
// folder at once leave one run's set, never a mix.
#include <catch2/catch.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "sanitized.hpp"
#include "temp_files.hpp"

namespace fs = std::filesystem;

namespace {
// The files an energy run writes for one form (tables and plots): a few hundred ms of work,
// most of it before the first file and some of it (gnuplot) between the first file and the last.
const std::vector<std::string> energy_args = {"energy", "--model", "blinn-phong", "--n", "1,16"};

pid_t start(std::vector<std::string> args, const fs::path& out) {
    args.insert(args.begin(), NORMZOO_VERIFY_BIN);
    args.push_back("--out");
    args.push_back(out.string());
    const pid_t pid = fork();
    if (pid == 0) {
        std::vector<char*> argv;
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        if (!std::freopen("/dev/null", "w", stdout) || !std::freopen("/dev/null", "w", stderr)) _exit(127);
        execv(argv[0], argv.data());
        _exit(127);
    }
    return pid;
}

int finish(pid_t pid) {
    int status = 0;
    waitpid(pid, &status, 0);
    return status;
}

using normzoo_test::fresh_dir;

std::map<std::string, std::string> contents(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::directory_iterator(dir)) files[e.path().filename().string()] = normzoo_test::slurp(e.path());
    return files;
}
}  // namespace

TEST_CASE("a run killed at any moment leaves the folder as it was or complete") {
    const int signal_number = GENERATE(SIGINT, SIGTERM);
    CAPTURE(signal_number);
    // The complete set, and how long a run takes.
    const fs::path reference = fresh_dir("reference");
    const auto t0 = std::chrono::steady_clock::now();
    REQUIRE(WEXITSTATUS(finish(start(energy_args, reference))) == 0);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto complete = contents(reference);
    REQUIRE(complete.size() > 10);

    // The folder before: every one of those files holds an older text.
    std::map<std::string, std::string> before;
    for (const auto& [name, text] : complete) before[name] = "an older " + name + "\n";
    int unchanged = 0, replaced = 0;
    // kills from early in the computation to beyond the reference's run time (a kill after it
    // ended finds the complete set); a run under load takes longer, so the kills go on later
    // until one has found it (up to 3x the reference's time); under the sanitizers every second
    // moment of these, over the same span (a run there takes seconds)
    const int step = normzoo_test::sanitized ? 2 : 1;
    for (int i = 1; i <= 30 || (replaced == 0 && i <= 60); i += step) {
        const fs::path dir = fresh_dir("killed");
        for (const auto& [name, text] : before) std::ofstream(dir / name, std::ios::binary) << text;
        const pid_t pid = start(energy_args, dir);
        std::this_thread::sleep_for(std::chrono::duration<double>(seconds * i / 20.0));
        kill(pid, signal_number);
        const int status = finish(pid);
        const auto after = contents(dir);
        CAPTURE(i, WIFSIGNALED(status), after.size());
        // no temporary left behind, and no mix of old and new
        const bool is_before = after == before, is_complete = after == complete;
        CHECK((is_before || is_complete));
        unchanged += is_before;
        replaced += is_complete;
        fs::remove_all(dir);
    }
    // killed runs were caught both before and after their writes (else the test saw nothing)
    CHECK(unchanged > 0);
    CHECK(replaced > 0);
    fs::remove_all(reference);
}

TEST_CASE("two runs writing one folder at once leave one run's tables, not a mix") {
    const fs::path dir = fresh_dir("concurrent");
    for (int round = 0; round < 4; ++round) {
        const pid_t a = start({"zoo", "--n", "0,1,2"}, dir);
        const pid_t b = start({"zoo", "--n", "4,8,16"}, dir);
        REQUIRE(WEXITSTATUS(finish(a)) == 0);
        REQUIRE(WEXITSTATUS(finish(b)) == 0);
        const auto files = contents(dir);
        int from_a = 0, from_b = 0;
        for (const auto& [name, text] : files) {
            if (name.rfind("gloss", 0) == 0) continue;  // the same whatever the exponents
            from_a += text.find("n = 0,1,2") != std::string::npos;
            from_b += text.find("n = 4,8,16") != std::string::npos;
        }
        CAPTURE(round, from_a, from_b);
        CHECK(from_a + from_b == 6);  // zoo and zoo-constants, as .md, .csv and .json
        CHECK((from_a == 0 || from_b == 0));
        for (const auto& [name, text] : files) CHECK(name.find(".tmp.") == std::string::npos);
    }
    fs::remove_all(dir);
}
