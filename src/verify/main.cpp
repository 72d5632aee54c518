// verify: the users' command. One request (the command line, or a scene) -> a plan of table jobs
// (plan.hpp) -> the library's typed results made into records (specs/, one per table) -> the
// output stage (output.hpp): exit 0 (every check holds), 1 (a check fails) or 2 (bad input).
#include <iostream>
#include <memory>
#include <vector>

#include "args.hpp"
#include "command_line.hpp"
#include "output.hpp"
#include "plan.hpp"
#include "progress.hpp"
#include "scene.hpp"

namespace {

int run(int argc, char** argv) {
    const auto cl = verify::parse_command_line(argc, argv, verify::table_names(), verify::named_only_tables());
    if (cl.help) {
        std::cout << *cl.help;
        return 0;
    }
    for (const auto& note : cl.notes) std::cerr << "verify: " << note << "\n";
    // On a terminal, how far the computation is (cleared before anything else is printed).
    verify::progress shown(verify::progress::wanted(cl.json));
    std::shared_ptr<const verify::scene> sc;
    if (!cl.scene_path.empty())
        sc = std::make_shared<const verify::scene>(verify::load_scene(cl.scene_path, verify::scene_model_ids()));
    const auto plan = verify::make_plan(cl, sc);
    // Compute everything first; only then touch the output folder.
    std::vector<verify::table_output> outputs;
    for (const auto& job : plan.jobs) {
        shown.step(job.name, job.unit);
        for (auto& t : job.run()) outputs.push_back(std::move(t));
    }
    shown.finish();
    return verify::deliver(cl, plan, outputs) ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const verify::bad_input& e) {
        std::cerr << "verify: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "verify: error: " << e.what() << "\n";
        return 1;
    }
}
