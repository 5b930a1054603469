#pragma once

#include <string>

namespace radarpr {

// Prints "warning: MESSAGE" on stderr the first time this process is given MESSAGE, and nothing
// the next times. A run opens a sequence several times (to inspect it before any work, to run
// it, as another dataset's database), so a problem met on opening would otherwise be said once
// per opening. Thread-safe.
void warn_once(const std::string& message);

}  // namespace radarpr
