#pragma once

#include <filesystem>

namespace radarpr {

// Files are written to a temporary name beside their target, then renamed over it, so that a
// reader never sees half a file. A process killed in between leaves its temporary behind; its
// name holds the writer's process id after ".tmp-" or ".tmp." (e.g. ".1700.png.tmp-4711-9f3a",
// "ab12.bin.tmp-4711-9f3a-0").
//
// Removes the temporaries in `folder` (not below it) whose writer no longer runs. Those of a
// live process, which may be writing them now, and every other file are kept. Errors are
// ignored: what is left is only wasted space, never read.
void remove_stale_temporary_files(const std::filesystem::path& folder);

// Whether no process with this id exists (kill(pid, 0) fails with ESRCH).
bool process_has_ended(long pid);

}  // namespace radarpr
