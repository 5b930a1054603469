#pragma once

#include <string>

#include "descriptors/descriptor.hpp"

namespace radarpr {

// Implemented, beside Descriptor, by descriptors whose learnt state is a codebook that can live in
// a file (`open_radvlad`: codebook=<.npy> loads one instead of training, save_codebook=<.npy>
// writes the trained one). The evaluation records the codebook's hash in the results, keys the
// cached values of a loaded codebook by that hash (a changed file never reuses old values), and
// never serves a descriptor that saves its codebook from the cache (its run must train and write).
class LearntCodebook {
 public:
  virtual ~LearntCodebook() = default;
  // SHA-256 (hex) of the codebook's float32 values, little-endian, row-major: equal to
  // hashlib.sha256(np.load(f).astype('<f4').tobytes()). Empty until trained or loaded.
  virtual std::string codebook_sha256() const = 0;
  // The file the codebook was loaded from; empty when it is trained.
  virtual std::string codebook_loaded_from() const = 0;
  // The file train() writes the codebook to; empty when none.
  virtual std::string codebook_saved_to() const = 0;
};

// The descriptor's LearntCodebook side, or nullptr.
inline const LearntCodebook* learnt_codebook_of(const Descriptor& descriptor) {
  return dynamic_cast<const LearntCodebook*>(&descriptor);
}

}  // namespace radarpr
