#include "evolve/record/checkpoint_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace robozoo {
namespace {

struct TempDir {
  std::string path;
  TempDir() {
    char tmpl[] = "/tmp/robozoo_ckw_XXXXXX";
    path = ::mkdtemp(tmpl);
  }
  ~TempDir() { std::system(("rm -rf '" + path + "'").c_str()); }
};

Checkpoint sample(int64_t evaluations) {
  Checkpoint c;
  c.run_id = "writer-test";
  c.software_version = "test";
  c.config = nlohmann::json::object();
  c.rng_state = "0";
  c.evaluations = evaluations;
  return c;
}

TEST(CheckpointWriter, WritesAtOnceOrInTheBackground) {
  for (bool background : {false, true}) {
    TempDir dir;
    CheckpointWriter w(dir.path + "/c.ckpt", background);
    EXPECT_EQ(w.background(), background);
    EXPECT_EQ(w.generations_written(), -1);
    w.write(sample(10), 1);
    w.write(sample(20), 2);  // in the background: waits for the first write
    w.wait();
    EXPECT_EQ(w.generations_written(), 2);
    EXPECT_EQ(read_checkpoint(dir.path + "/c.ckpt").evaluations, 20);
  }
}

TEST(CheckpointWriter, ABackgroundFailureSurfacesAtTheNextCall) {
  CheckpointWriter w("/nonexistent-folder/c.ckpt", true);
  w.write(sample(1), 1);  // starts; fails on its thread
  EXPECT_THROW(w.wait(), std::runtime_error);
  EXPECT_NO_THROW(w.wait());  // reported once
  EXPECT_EQ(w.generations_written(), -1);
  w.write(sample(2), 2);
  EXPECT_THROW(w.write(sample(3), 3), std::runtime_error);  // the previous write's error: 3 is not started
  EXPECT_NO_THROW(w.wait());
  EXPECT_EQ(w.generations_written(), -1);
}

TEST(CheckpointWriter, AFailureAtOnceThrowsFromWrite) {
  CheckpointWriter w("/nonexistent-folder/c.ckpt", false);
  EXPECT_THROW(w.write(sample(1), 1), std::runtime_error);
}

}  // namespace
}  // namespace robozoo
