#include "animkit/io/point_cache.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/temp_files.h"
#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"

namespace animkit {
namespace {

namespace fs = std::filesystem;
using testing_support::fresh_dir;
using testing_support::read_file;

TEST(PointCache, FramesReadBackAsWritten) {
  const fs::path dir = fresh_dir("pc2_roundtrip");
  auto sim = *ClothSimulator::create(make_grid_cloth({.cells = 4}), {});
  std::vector<Eigen::VectorXd> written;
  {
    auto writer = Pc2Writer::open(dir / "cloth.pc2", sim.model().particle_count());
    ASSERT_TRUE(writer);
    for (int frame = 0; frame < 20; ++frame) {
      written.push_back(sim.state().positions);
      ASSERT_TRUE(writer->add_frame(sim.state().positions));
      ASSERT_TRUE(sim.step(1.0 / 60.0));
    }
    EXPECT_FALSE(fs::exists(dir / "cloth.pc2"));  // not before finish()
    ASSERT_TRUE(writer->finish());
  }
  EXPECT_FALSE(fs::exists(dir / "cloth.pc2.tmp"));
  const auto cache = read_pc2(dir / "cloth.pc2");
  ASSERT_TRUE(cache) << cache.error().message;
  EXPECT_EQ(cache->points, 25);
  EXPECT_EQ(cache->start_frame, 0.0f);
  EXPECT_EQ(cache->sample_rate, 1.0f);
  ASSERT_EQ(cache->frames.size(), 20u);
  for (std::size_t f = 0; f < written.size(); ++f) {
    for (Eigen::Index i = 0; i < written[f].size(); ++i) {
      EXPECT_EQ(cache->frames[f][static_cast<std::size_t>(i)], static_cast<float>(written[f][i]));
    }
  }
  // Header: the 12-byte signature, then version 1 and the point count.
  const std::string bytes = read_file(dir / "cloth.pc2");
  EXPECT_EQ(bytes.substr(0, 12), std::string("POINTCACHE2\0", 12));
  EXPECT_EQ(bytes.size(), 32u + 20u * 25u * 3u * 4u);
}

TEST(PointCache, AnUnfinishedWriterLeavesNothing) {
  const fs::path dir = fresh_dir("pc2_unfinished");
  {
    auto writer = Pc2Writer::open(dir / "cloth.pc2", 3);
    ASSERT_TRUE(writer);
    ASSERT_TRUE(writer->add_frame(Eigen::VectorXd::Zero(9)));
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(PointCache, RejectsFilesThatAreNotPointCaches) {
  const fs::path dir = fresh_dir("pc2_bad");
  std::ofstream(dir / "text.pc2") << "hello, this is not a point cache at all";
  EXPECT_EQ(read_pc2(dir / "text.pc2").error().message,
            (dir / "text.pc2").string() + " is not a PC2 point cache (no POINTCACHE2 header)");
  {
    auto writer = Pc2Writer::open(dir / "short.pc2", 2);
    ASSERT_TRUE(writer->add_frame(Eigen::VectorXd::Ones(6)));
    ASSERT_TRUE(writer->finish());
  }
  fs::resize_file(dir / "short.pc2", 32 + 10);
  EXPECT_EQ(
      read_pc2(dir / "short.pc2").error().message,
      (dir / "short.pc2").string() +
          " is truncated: its header promises 1 frames of 2 points, the file has 42 bytes (room "
          "for 0 frames)");
  {
    auto writer = Pc2Writer::open(dir / "wrong.pc2", 2);
    EXPECT_FALSE(writer->add_frame(Eigen::VectorXd::Ones(5)));  // 5 coordinates for 2 points
  }
  EXPECT_FALSE(read_pc2(dir / "missing.pc2"));
}

// A PC2 header: signature, version 1, the counts, start frame 0 and sample rate 1.
std::string pc2_header(std::int32_t points, std::int32_t samples) {
  std::string bytes("POINTCACHE2\0", 12);
  const auto put = [&](auto value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
  };
  put(std::int32_t{1});
  put(points);
  put(0.0f);
  put(1.0f);
  put(samples);
  return bytes;
}

TEST(PointCache, RefusesAHeaderOfEmptyFramesBeforeAllocating) {
  // Regression: 0 points and 1.3e9 samples passed the size check (0 bytes of frames) and then
  // allocated 1.3e9 empty frames (tens of gigabytes).
  const fs::path dir = fresh_dir("pc2_empty_frames");
  std::ofstream(dir / "zero.pc2", std::ios::binary) << pc2_header(0, 1'300'000'000);
  const auto cache = read_pc2(dir / "zero.pc2");
  ASSERT_FALSE(cache);
  EXPECT_EQ(cache.error().message,
            (dir / "zero.pc2").string() + " has 1300000000 samples of 0 points");
}

TEST(PointCache, TheSizeMustMatchTheHeaderExactly) {
  const fs::path dir = fresh_dir("pc2_size");
  std::ofstream(dir / "long.pc2", std::ios::binary) << pc2_header(1, 1) + std::string(12 + 5, 'x');
  EXPECT_EQ(read_pc2(dir / "long.pc2").error().message,
            (dir / "long.pc2").string() +
                " has 49 bytes, more than the 44 of its header's 1 frames of 1 points");
  std::ofstream(dir / "huge.pc2", std::ios::binary) << pc2_header(2'000'000'000, 2'000'000'000);
  EXPECT_EQ(read_pc2(dir / "huge.pc2").error().message,
            (dir / "huge.pc2").string() +
                " is truncated: its header promises 2000000000 frames of 2000000000 points, the "
                "file has 32 bytes (room for 0 frames)");
  std::ofstream(dir / "empty.pc2", std::ios::binary) << pc2_header(3, 0);
  const auto empty = read_pc2(dir / "empty.pc2");
  ASSERT_TRUE(empty) << empty.error().message;
  EXPECT_EQ(empty->points, 3);
  EXPECT_TRUE(empty->frames.empty());
  fs::create_directory(dir / "folder.pc2");
  EXPECT_EQ(read_pc2(dir / "folder.pc2").error().message,
            (dir / "folder.pc2").string() + ": is a folder, not a file");
}

TEST(ClothObj, VerticesInParticleOrderAndOneBasedFaces) {
  const auto built = *build_cloth(make_grid_cloth({.cells = 1}));
  const std::string obj = cloth_obj(built.model, built.state);
  EXPECT_NE(obj.find("\nv 0 1.5 -1\n"), std::string::npos) << obj;
  EXPECT_NE(obj.find("\nv 2 1.5 1\n"), std::string::npos);
  EXPECT_NE(obj.find("\nf 1 3 4\n"), std::string::npos);
  EXPECT_NE(obj.find("\nf 1 4 2\n"), std::string::npos);
}

}  // namespace
}  // namespace animkit
