// Running one of this build's programs (inkray-render, inkray-merge, ...) from a test:
// what it printed and how it exited.
#pragma once

#include "tests/support/file_helpers.h"

#include <string>

namespace inkray::testing {

struct RunResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// `program` with `args`, behind `wrapper` where one is given ("timeout 60 ").
inline RunResult run_program(const std::string& program, const std::string& args,
                             const std::string& wrapper = "") {
  RunResult r;
  r.output =
      run_command(wrapper + std::string(INKRAY_BINARY_DIR) + "/bin/" + program + " " + args, &r.exit_code);
  return r;
}

}  // namespace inkray::testing
