// The log panel: loader warnings and errors, render statistics, notes.
#pragma once

#include "ui/model/log.h"

namespace inkray {

void draw_log_panel(Log& log);

}  // namespace inkray
