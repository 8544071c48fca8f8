// The plot's word on a model whose shells are not all closed solids (one or two lines on
// stderr), and the measurements behind it for --stats.
#pragma once
#include <string>

#include "pipeline/mesh_repair.h"

namespace haloplot::host {

// Empty when every shell is a closed solid. Open shells: with the open sides measured
// (RepairReport::measured), either the --weld EPS that closes their gaps and how many open
// sides it closes, or that they are open as made (no corner of another open side near: no
// weld closes them, and the hidden lines are right, every face hiding from both sides). A
// shell that cannot be oriented: one place it shows (FILE:LINE, or the coordinates), on its
// own line when there are open shells too. With --weld `weld` given (RepairReport::compared),
// a line more if it leaves more to mend than the default weld: more sides on three or more
// faces, more shells that cannot be oriented or more open sides.
std::string shells_note(const std::string& path, const RepairReport& r, const std::string& weld);

// The measurements as key=value lines (--stats): open_sides=..., weld_hint=... Empty when
// nothing was measured.
std::string shells_stats(const RepairReport& r, double scale);

}  // namespace haloplot::host
