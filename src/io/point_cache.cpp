#include "animkit/io/point_cache.h"

#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <utility>

#include "animkit/io/atomic_write.h"
#include "animkit/io/file_bytes.h"

namespace animkit {

static_assert(std::endian::native == std::endian::little, "PC2 files are little-endian");

namespace {

constexpr char kSignature[12] = "POINTCACHE2";  // with its terminating NUL: 12 bytes
constexpr long kSampleCountOffset = 12 + 4 + 4 + 4 + 4;

struct Pc2Header {
  char signature[12];
  std::int32_t version;
  std::int32_t points;
  float start_frame;
  float sample_rate;
  std::int32_t samples;
};
static_assert(sizeof(Pc2Header) == 32);

std::string io_error(const std::filesystem::path& path, const char* what) {
  return std::string("cannot ") + what + " " + path.string() + ": " + std::strerror(errno);
}

}  // namespace

std::string cloth_obj(const ClothModel& model, const ClothState& state) {
  std::ostringstream obj;
  obj.precision(9);
  obj << "# animkit cloth: " << model.particle_count() << " particles, " << model.triangles.size()
      << " triangles; vertex order = cloth.pc2 point order\n";
  for (int i = 0; i < model.particle_count(); ++i) {
    const Vec3 p = state.position(i);
    obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  for (const auto& t : model.triangles) {
    obj << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
  return obj.str();
}

Pc2Writer::Pc2Writer(AtomicFile file, int points)
    : file_(std::move(file)), points_(points), buffer_(3 * static_cast<std::size_t>(points)) {}

Pc2Writer::Pc2Writer(Pc2Writer&& other) noexcept
    : file_(std::move(other.file_)),
      points_(other.points_),
      samples_(other.samples_),
      buffer_(std::move(other.buffer_)) {
  other.file_.reset();
}

// Never finished: the AtomicFile's destructor removes the temporary.
Pc2Writer::~Pc2Writer() = default;

Result<Pc2Writer> Pc2Writer::open(const std::filesystem::path& path, int points,
                                  float start_frame) {
  auto file = AtomicFile::create(path);
  if (!file) return fail(file.error().message);
  Pc2Header header{};
  std::memcpy(header.signature, kSignature, sizeof kSignature);
  header.version = 1;
  header.points = points;
  header.start_frame = start_frame;
  header.sample_rate = 1.0f;
  header.samples = 0;  // patched by finish()
  if (std::fwrite(&header, sizeof header, 1, file->stream()) != 1) {
    return fail(io_error(path, "write"));
  }
  return Pc2Writer(std::move(*file), points);
}

Result<void> Pc2Writer::add_frame(const Eigen::VectorXd& positions) {
  if (!file_) return fail("cannot write a PC2 file that is already finished");
  const std::filesystem::path& path = file_->path();
  if (positions.size() != static_cast<Eigen::Index>(buffer_.size())) {
    return fail("cannot write " + path.string() + ": a frame of " +
                std::to_string(positions.size()) + " coordinates for " + std::to_string(points_) +
                " points");
  }
  for (std::size_t i = 0; i < buffer_.size(); ++i) {
    buffer_[i] = static_cast<float>(positions[static_cast<Eigen::Index>(i)]);
  }
  if (std::fwrite(buffer_.data(), sizeof(float), buffer_.size(), file_->stream()) !=
      buffer_.size()) {
    return fail(io_error(path, "write"));
  }
  ++samples_;
  return {};
}

Result<void> Pc2Writer::finish() {
  if (!file_) return fail("cannot write a PC2 file that is already finished");
  const std::int32_t samples = samples_;
  const bool patched = std::fseek(file_->stream(), kSampleCountOffset, SEEK_SET) == 0 &&
                       std::fwrite(&samples, sizeof samples, 1, file_->stream()) == 1;
  auto committed = file_->commit(patched);
  file_.reset();
  return committed;
}

Result<PointCache> parse_pc2(std::span<const std::byte> bytes, std::string_view name) {
  const auto problem = [&](const std::string& what) {
    return fail(std::string(name) + " " + what);
  };
  Pc2Header header{};
  if (bytes.size() < sizeof header) {
    return problem("is not a PC2 point cache (" + std::to_string(bytes.size()) +
                   " bytes, shorter than its 32-byte header)");
  }
  std::memcpy(&header, bytes.data(), sizeof header);
  if (std::memcmp(header.signature, kSignature, sizeof kSignature) != 0) {
    return problem("is not a PC2 point cache (no POINTCACHE2 header)");
  }
  if (header.version != 1) {
    return problem("has PC2 version " + std::to_string(header.version) + " (expected 1)");
  }
  if (header.points < 0 || header.samples < 0) {
    return problem("has a negative point or sample count (" + std::to_string(header.points) +
                   " points, " + std::to_string(header.samples) + " samples)");
  }
  // Frames without points take no bytes, so the size check below cannot bound them: a corrupt
  // header could otherwise ask for a billion empty frames.
  if (header.points == 0 && header.samples > 0) {
    return problem("has " + std::to_string(header.samples) + " samples of 0 points");
  }
  // Checked by division first: samples x points x 12 can overflow 64 bits.
  const std::uint64_t frame_bytes = 12 * static_cast<std::uint64_t>(header.points);
  const std::uint64_t frame_room = bytes.size() - sizeof header;
  const std::string promise =
      std::to_string(header.samples) + " frames of " + std::to_string(header.points) + " points";
  if (frame_bytes > 0 && static_cast<std::uint64_t>(header.samples) > frame_room / frame_bytes) {
    return problem("is truncated: its header promises " + promise + ", the file has " +
                   std::to_string(bytes.size()) + " bytes (room for " +
                   std::to_string(frame_room / frame_bytes) + " frames)");
  }
  const std::uint64_t expected =
      sizeof header + frame_bytes * static_cast<std::uint64_t>(header.samples);
  if (bytes.size() != expected) {
    return problem("has " + std::to_string(bytes.size()) + " bytes, more than the " +
                   std::to_string(expected) + " of its header's " + promise);
  }
  PointCache cache;
  cache.points = header.points;
  cache.start_frame = header.start_frame;
  cache.sample_rate = header.sample_rate;
  const std::size_t count = 3 * static_cast<std::size_t>(header.points);
  cache.frames.reserve(static_cast<std::size_t>(header.samples));
  const std::byte* data = bytes.data() + sizeof header;
  for (int s = 0; s < header.samples; ++s, data += count * sizeof(float)) {
    std::vector<float>& frame = cache.frames.emplace_back(count);
    std::memcpy(frame.data(), data, count * sizeof(float));
  }
  return cache;
}

Result<PointCache> read_pc2(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path, kMaxPc2FileBytes);
  if (!bytes) return fail(bytes.error().message);
  return parse_pc2(std::as_bytes(std::span(*bytes)), path.string());
}

}  // namespace animkit
