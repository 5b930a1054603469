#pragma once

#include <vector>

#include "descriptors/descriptor.hpp"
#include "evaluation/retrieval/blocked_l2_search.hpp"

namespace radarpr {

// Checks, on a sample of the values, the premise of a fast retrieval path a descriptor declares
// (descriptor.hpp, RetrievalMethod), so that a wrong declaration stops the evaluation with an
// error instead of silently returning matches that are not the nearest by distance():
// - kdtree: for each sampled query, distance() must not decrease as the L2 distance of the
//   search keys grows (beyond float rounding);
// - exhaustive_l2: distance() must equal the L2 distance of the values.
// exhaustive needs no premise; key_then_rerank is an approximation the descriptor states.
// Throws std::invalid_argument naming the method, the first offending pair and both distances.
// Cost: at most kSampleQueries x kSampleDatabase distance() calls.
void check_retrieval_declaration(const Descriptor& descriptor,
                                 const std::vector<DescriptorValue>& database,
                                 const std::vector<DescriptorValue>& queries);

// The exhaustive_l2 premise on values read where they lie (a memory-mapped matrix): the same
// sample and error as check_retrieval_declaration.
void check_exhaustive_l2_rows(const Descriptor& descriptor, const L2Rows& database,
                              const L2Rows& queries);

}  // namespace radarpr
