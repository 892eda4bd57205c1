#include "render/codec/video_encoder.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "tests/render/decode_video.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::render {
namespace {

using robozoo::testing::file_exists;
using robozoo::testing::TempDir;

constexpr size_t kRecordedDefaultSize = 2037;
constexpr uint64_t kRecordedDefaultHash = 15015131332625733045ull;

Image gradient(int w, int h, int shift) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.set(x, y,
              {static_cast<uint8_t>((x + shift) * 3), static_cast<uint8_t>(y * 4), static_cast<uint8_t>(shift * 9)});
  return img;
}

std::string bytes_of(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(VideoEncoder, WritesBrowserFriendlyH264) {
  TempDir dir;
  EncoderOptions o;
  o.width = 64;
  o.height = 48;
  o.fps = 25;
  {
    VideoEncoder enc(dir / "v.mp4", o);
    for (int i = 0; i < 12; ++i) enc.add_frame(gradient(64, 48, i));
    EXPECT_FALSE(file_exists(dir / "v.mp4"));  // written under another name until finished
    enc.finish();
    EXPECT_EQ(enc.frames(), 12);
  }
  const auto v = testing::decode_video(dir / "v.mp4");
  ASSERT_TRUE(v.ok) << v.error;
  EXPECT_EQ(v.codec, "h264");
  EXPECT_EQ(v.pix_fmt, "yuv420p");
  EXPECT_EQ(v.width, 64);
  EXPECT_EQ(v.height, 48);
  EXPECT_DOUBLE_EQ(v.fps, 25.0);
  EXPECT_EQ(v.luma.size(), 12u);
  EXPECT_TRUE(v.moov_before_mdat);
  EXPECT_FALSE(file_exists(dir / "v.mp4.part"));
}

TEST(VideoEncoder, SameFramesSameBytes) {
  TempDir dir;
  EncoderOptions o;
  o.width = 64;
  o.height = 48;
  for (const char* name : {"a.mp4", "b.mp4"}) {
    VideoEncoder enc(dir / name, o);
    for (int i = 0; i < 8; ++i) enc.add_frame(gradient(64, 48, i));
    enc.finish();
  }
  EXPECT_EQ(bytes_of(dir / "a.mp4"), bytes_of(dir / "b.mp4"));
}

// libx264's output depends on its thread count, and its own choice (threads 0)
// follows the machine's cores: by default one thread, so a log gives the same
// video on every machine.
TEST(VideoEncoder, DefaultIsOneThreadSoBytesDoNotFollowTheCores) {
  EXPECT_EQ(EncoderOptions{}.threads, 1);
  TempDir dir;
  for (int threads : {-1, 1}) {
    EncoderOptions o;
    o.width = 64;
    o.height = 48;
    if (threads > 0) o.threads = threads;
    VideoEncoder enc(dir / (threads > 0 ? "one.mp4" : "default.mp4"), o);
    for (int i = 0; i < 8; ++i) enc.add_frame(gradient(64, 48, i));
    enc.finish();
  }
  EXPECT_EQ(bytes_of(dir / "default.mp4"), bytes_of(dir / "one.mp4"));
}

uint64_t fnv1a(const std::string& bytes) {
  uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string encode_gradients(const std::string& path, const EncoderOptions& o, int frames) {
  VideoEncoder enc(path, o);
  for (int i = 0; i < frames; ++i) enc.add_frame(gradient(o.width, o.height, i));
  enc.finish();
  return bytes_of(path);
}

// The default settings keep their bytes: size and FNV-1a hash recorded with the
// encoder as it was before --fast existed (libx264 and libswscale of this
// machine's packages; another libx264 build may give other bytes).
TEST(VideoEncoder, DefaultBytesAreTheRecordedOnes) {
  TempDir dir;
  EncoderOptions o;
  o.width = 64;
  o.height = 48;
  const std::string bytes = encode_gradients(dir / "default.mp4", o, 12);
  EXPECT_EQ(bytes.size(), kRecordedDefaultSize);
  EXPECT_EQ(fnv1a(bytes), kRecordedDefaultHash);
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

/// Set in the copy of this test that SameBytesWhateverTheHeapHeld starts under AddressSanitizer:
/// the file to encode the gradients into.
constexpr const char* kHeapPatternOut = "ROBOZOO_TEST_HEAP_PATTERN_OUT";

EncoderOptions small_video() {
  EncoderOptions o;
  o.width = 64;
  o.height = 48;
  return o;
}

/// Encodes the gradients into `path` with every new heap block filled with `pattern` first.
/// glibc's malloc does it in this process (M_PERTURB, which also fills freed blocks).
/// AddressSanitizer's malloc ignores mallopt and fills new blocks with its own byte, set when
/// a process starts (ASAN_OPTIONS malloc_fill_byte): there this test runs again in a new
/// process for each pattern.
std::string encode_with_heap_pattern(const std::string& path, int pattern) {
  if (!kAddressSanitizer) {
    if (mallopt(M_PERTURB, pattern) != 1) throw std::runtime_error("glibc refused mallopt(M_PERTURB)");
    const std::string bytes = encode_gradients(path, small_video(), 12);
    mallopt(M_PERTURB, 0);
    return bytes;
  }
  const char* given = std::getenv("ASAN_OPTIONS");
  const std::string options = (given && *given ? std::string(given) + ":" : std::string()) +
                              "malloc_fill_byte=" + std::to_string(pattern) + ":max_malloc_fill_size=1073741824";
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    setenv("ASAN_OPTIONS", options.c_str(), 1);
    setenv(kHeapPatternOut, path.c_str(), 1);
    execl("/proc/self/exe", "/proc/self/exe", "--gtest_filter=VideoEncoder.SameBytesWhateverTheHeapHeld",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("the test's copy with heap pattern " + std::to_string(pattern) + " failed (status " +
                             std::to_string(status) + ")");
  return bytes_of(path);
}

// The same frames give the same bytes whatever the heap held before: every new
// block is filled with a pattern first (encode_with_heap_pattern), so an encoder
// that read memory it never wrote would give other bytes under each pattern.
TEST(VideoEncoder, SameBytesWhateverTheHeapHeld) {
  if (const char* out = std::getenv(kHeapPatternOut)) {  // the copy started under AddressSanitizer
    encode_gradients(out, small_video(), 12);
    return;
  }
  TempDir dir;
  for (int pattern : {165, 17, 0}) {
    const std::string bytes = encode_with_heap_pattern(dir / ("p" + std::to_string(pattern) + ".mp4"), pattern);
    EXPECT_EQ(bytes.size(), kRecordedDefaultSize) << "heap pattern " << pattern;
    EXPECT_EQ(fnv1a(bytes), kRecordedDefaultHash) << "heap pattern " << pattern;
  }
}

// --fast: libx264's faster preset on its own thread count; everything else as given.
TEST(VideoEncoder, FastIsTheFasterPresetOnLibx264sThreads) {
  EncoderOptions given;
  given.width = 64;
  given.height = 48;
  given.crf = 30;
  given.fps = 30;
  const EncoderOptions fast = fast_encoder(given);
  EXPECT_EQ(fast.preset, "superfast");
  EXPECT_EQ(fast.threads, 0);
  EXPECT_EQ(fast.width, 64);
  EXPECT_EQ(fast.height, 48);
  EXPECT_EQ(fast.crf, 30);
  EXPECT_EQ(fast.fps, 30);
  TempDir dir;
  const std::string a = encode_gradients(dir / "default.mp4", given, 12);
  const std::string b = encode_gradients(dir / "fast.mp4", fast, 12);
  EXPECT_NE(a, b);  // other settings, other bytes
  const auto v = testing::decode_video(dir / "fast.mp4");
  ASSERT_TRUE(v.ok) << v.error;
  EXPECT_EQ(v.codec, "h264");
  EXPECT_EQ(v.pix_fmt, "yuv420p");
  EXPECT_EQ(v.luma.size(), 12u);
  EXPECT_DOUBLE_EQ(v.fps, 30.0);
  EXPECT_TRUE(v.moov_before_mdat);
}

TEST(VideoEncoder, OddSizesAndBadFrames) {
  TempDir dir;
  EncoderOptions o;
  o.width = 65;
  o.height = 48;
  try {
    VideoEncoder enc(dir / "odd.mp4", o);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("even"), std::string::npos);
  }
  o.width = 64;
  o.crf = 60;
  EXPECT_THROW(VideoEncoder(dir / "crf.mp4", o), std::invalid_argument);
  o.crf = 23;
  o.preset = "no-such-preset";
  EXPECT_THROW(VideoEncoder(dir / "preset.mp4", o), std::runtime_error);
  o.preset = "veryfast";
  EXPECT_THROW(VideoEncoder(dir / "no/such/dir/x.mp4", o), std::runtime_error);
  {
    VideoEncoder enc(dir / "unfinished.mp4", o);
    EXPECT_THROW(enc.add_frame(gradient(32, 48, 0)), std::invalid_argument);
    enc.add_frame(gradient(64, 48, 0));
  }  // never finished: nothing left behind
  EXPECT_FALSE(file_exists(dir / "unfinished.mp4"));
  EXPECT_FALSE(file_exists(dir / "unfinished.mp4.part"));
}

}  // namespace
}  // namespace robozoo::render
