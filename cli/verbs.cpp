#include "cli/verbs.hpp"

namespace radarpr::cli {

// One line per verb, in the order `radarpr --help` lists them. VERB(name) stands for the
// function `Verb name_verb()` that cli/name_command.cpp defines.
#define RADARPR_FOR_EACH_VERB(VERB) \
  VERB(run)                         \
  VERB(report)                      \
  VERB(compare)                     \
  VERB(inspect)                     \
  VERB(list)                        \
  VERB(extract)                     \
  VERB(export)                      \
  VERB(simulate)                    \
  VERB(bench)                       \
  VERB(plan)                        \
  VERB(run_unit)                    \
  VERB(status)                      \
  VERB(merge)

#define RADARPR_DECLARE_VERB(name) Verb name##_verb();
RADARPR_FOR_EACH_VERB(RADARPR_DECLARE_VERB)
#undef RADARPR_DECLARE_VERB

std::vector<Verb> all_verbs() {
#define RADARPR_LIST_VERB(name) name##_verb(),
  return {RADARPR_FOR_EACH_VERB(RADARPR_LIST_VERB)};
#undef RADARPR_LIST_VERB
}

}  // namespace radarpr::cli
