#pragma once

#include <filesystem>
#include <string>

namespace radarpr {

// Results are written to a staging folder beside their destination (`<name>.partial.<pid>`),
// then moved into place, so that a failure or a kill never leaves a half-written file where a
// reader would trust it.

// Removes the staging folders `<folder>/<prefix><pid>` that a run, report or comparison killed
// midway left behind: those whose process no longer exists (a live one keeps its own).
void remove_stale_staging(const std::filesystem::path& folder, const std::string& prefix);

// Moves every entry of `staging` into `target` (replacing entries of the same name; folders
// merged, so other files in them stay) and removes `staging`. Nothing in `target` that
// `staging` does not hold is touched.
void publish_staged(const std::filesystem::path& staging, const std::filesystem::path& target);

}  // namespace radarpr
