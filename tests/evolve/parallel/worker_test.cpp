#include "evolve/parallel/worker.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace robozoo {
namespace {

Bytes reverse(const Bytes& in) { return Bytes(in.rbegin(), in.rend()); }

TEST(Worker, RunJobReturnsTheFunctionsOutput) {
  const Result r = run_job(reverse, Job{5, {1, 2, 3}});
  EXPECT_EQ(r.index, 5u);
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.payload, (Bytes{3, 2, 1}));
}

TEST(Worker, ExceptionsBecomeFailures) {
  const Result a = run_job([](const Bytes&) -> Bytes { throw std::runtime_error("no joints"); }, Job{2, {}});
  EXPECT_EQ(a.index, 2u);
  EXPECT_FALSE(a.ok);
  EXPECT_EQ(a.error, "no joints");
  const Result b = run_job([](const Bytes&) -> Bytes { throw 17; }, Job{3, {}});
  EXPECT_FALSE(b.ok);
  EXPECT_NE(b.error.find("unknown exception"), std::string::npos);
}

TEST(Worker, ServeFrameAnswersJobsAndStopsOnShutdown) {
  const auto reply = serve_frame(reverse, decode_message(encode_job(Job{8, {4, 5}})));
  ASSERT_TRUE(reply.has_value());
  const Result r = result_from_frame(decode_message(*reply));
  EXPECT_EQ(r.index, 8u);
  EXPECT_EQ(r.payload, (Bytes{5, 4}));

  const auto failed = serve_frame([](const Bytes&) -> Bytes { throw std::invalid_argument("bad"); },
                                  decode_message(encode_job(Job{9, {}})));
  ASSERT_TRUE(failed.has_value());
  const Frame f = decode_message(*failed);
  EXPECT_EQ(f.kind, FrameKind::Failure);
  EXPECT_EQ(result_from_frame(f).error, "bad");

  EXPECT_FALSE(serve_frame(reverse, decode_message(encode_shutdown())).has_value());
  EXPECT_THROW(serve_frame(reverse, decode_message(encode_result(Result{1, true, {}, ""}))), ProtocolError);
}

}  // namespace
}  // namespace robozoo
