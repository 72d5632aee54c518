// The command's records and tables are the command's (namespace verify), and read the library's
// names unqualified, as they did when they shared its namespace; the library's detail helpers
// stay reachable as detail:: beside the command's own (docs/architecture.md, "The command").
#pragma once

namespace normzoo::detail {}  // declared by the library's headers; named here

namespace verify {
using namespace normzoo;
namespace detail {
using namespace normzoo::detail;
}
}  // namespace verify
