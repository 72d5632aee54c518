// The preprocessor a shader file goes through before anything else reads its code
// (docs/brdf-code.md#the-preprocessor): mcpp, run as a child process under caps, on copies of the
// file and of the files it includes, each screened going in (shader_screen.hpp) with its
// #include directives resolved here, inside the include folders only. What comes out is plain
// code, every line mapped back to its file and line; no directive is left for validation or the
// translation to read.
#pragma once
#include <string>
#include <vector>

#include "brdf_file.hpp"
#include "child_process.hpp"

namespace verify {

struct preprocess_options {
    std::vector<std::string> defines;       // NAME or NAME=VALUE, as --define gives them
    std::vector<std::string> include_dirs;  // as --include-dir gives them
};

// The source with its code preprocessed (code, origin, version, extensions); bad_input naming the
// file and line, the option, or the cap that tripped.
shader_source preprocess_shader(const shader_source& raw, const preprocess_options& options, const shader_caps& caps);

// A shader file read (read_shader_file) and preprocessed under the environment's caps.
shader_source read_preprocessed(const std::string& path, const preprocess_options& options = {});

}  // namespace verify
