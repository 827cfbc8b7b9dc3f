#pragma once
// Cloth animation files Blender opens: the rest mesh as Wavefront OBJ and every frame's
// particle positions as a PC2 point cache (what Blender's Mesh Cache modifier reads).
//
// PC2 layout (little-endian): char[12] "POINTCACHE2\0", int32 version = 1, int32 points,
// float32 start frame, float32 sample rate, int32 samples, then samples x points x 3 float32.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "animkit/cloth/cloth_model.h"
#include "animkit/core/result.h"
#include "animkit/io/atomic_write.h"

namespace animkit {

/// The mesh as OBJ text: one `v` per particle (in particle order, which is the PC2's point
/// order) and one `f` per triangle.
std::string cloth_obj(const ClothModel& model, const ClothState& state);

/// Streams frames into a temporary file (AtomicFile) renamed to `path` on finish(), so the file
/// is written whole or not at all: a writer destroyed before finish() removes its temporary.
class Pc2Writer {
 public:
  /// `start_frame`: the header's first frame (where Blender's Mesh Cache modifier, given the
  /// same frame_start, shows the first sample).
  static Result<Pc2Writer> open(const std::filesystem::path& path, int points,
                                float start_frame = 0.0f);
  /// Takes over `other`'s unfinished file; `other` is left holding none.
  Pc2Writer(Pc2Writer&& other) noexcept;
  /// Not assignable: a writer stays bound to the file it opened.
  Pc2Writer& operator=(Pc2Writer&&) = delete;
  /// An unfinished file is abandoned: its temporary is removed, `path` stays as it was.
  ~Pc2Writer();

  /// Appends one frame: 3 * points coordinates.
  Result<void> add_frame(const Eigen::VectorXd& positions);
  /// Writes the sample count into the header, flushes and renames into place.
  Result<void> finish();

 private:
  Pc2Writer(AtomicFile file, int points);
  std::optional<AtomicFile> file_;  // empty once finished
  int points_ = 0;
  int samples_ = 0;
  std::vector<float> buffer_;
};

/// A PC2 file read back: frames[k] holds 3 * points coordinates.
struct PointCache {
  int points = 0;  ///< points per frame (the header's)
  /// The header's first frame (Pc2Writer::open's `start_frame`).
  float start_frame = 0.0f, sample_rate = 1.0f;  ///< frames between samples (1 as written here)
  std::vector<std::vector<float>> frames;        ///< one per sample, (x, y, z) per point
};
/// Largest point cache read (a 100 x 100 cloth for 10 000 frames is about 1.2 GB).
constexpr std::uintmax_t kMaxPc2FileBytes = std::uintmax_t{2} << 30;

/// The point cache held in `bytes`. `name` (the file's) starts every error: no POINTCACHE2
/// header, an unknown version, negative counts, frames with no points, or a size that is not
/// exactly the header's 32 bytes plus samples x points x 12 (checked before allocating).
Result<PointCache> parse_pc2(std::span<const std::byte> bytes, std::string_view name);

/// parse_pc2 of the file's bytes; also errors for a missing, unreadable or huge file.
Result<PointCache> read_pc2(const std::filesystem::path& path);

}  // namespace animkit
