#pragma once
// The short summary table `animkit ik` and `animkit demo` print: one row per drawing.
#include <string_view>

#include "animkit/kinematics/drawing_session.h"

namespace animkit::cli {

void print_ik_table_header();
void print_ik_table_row(std::string_view shape, std::string_view solver, const DrawingSummary& s);

}  // namespace animkit::cli
