// robozoo-view --lcm-url on a real LCM bus, inside a private network namespace:
// a short run's log played by lcm-logplayer reaches the view's state whole.
// Runs alone (RUN_SERIAL: the name ends in _live_test).
#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include "evolve/io/event_log.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::view {
namespace {

using namespace robozoo::testing;

const std::string kUrl = "udpm://239.255.76.67:7667?ttl=0";

/// Runs `inner` (a shell script) in a private network namespace with
/// multicast on the loopback interface.
Outcome in_namespace(const std::string& inner) {
  return run_shell("timeout 150 unshare -n sh -c \"ip link set lo up && ip route add 224.0.0.0/4 dev lo && " + inner +
                   "\"");
}

// Every message goes through the bus feed's LCM subscription (under
// tools/test.sh --sanitize, a subscription called through a pointer to member
// function ended the program at the first message).
TEST(ViewBusFeed, FollowsARunPlayedOnTheBus) {
  TempDir dir;
  const std::string log = dir / "run.lcmlog";
  const Outcome evolve = run_shell(bin("robozoo-evolve") + " --log '" + log +
                                   "' --seed 3 --population 6 --generations 2 --steps 100 --quiet");
  ASSERT_EQ(evolve.status, 0) << evolve.output;
  const size_t messages = read_event_log(log).records.size();
  ASSERT_GT(messages, 4u);
  const std::string view = bin("robozoo-view") + " --lcm-url '" + kUrl +
                           "' --port 0 --idle-exit 2 --stream-timeout 1 > '" + (dir / "view.txt") + "' 2>&1";
  const Outcome o = in_namespace("(" + view + " & V=\\$!; sleep 1; lcm-logplayer -s 1000 -l '" + kUrl + "' '" + log +
                                 "'; wait \\$V; exit \\$?)");
  const std::string out = read_file(dir / "view.txt");
  ASSERT_EQ(o.status, 0) << o.output << "\n" << out;
  EXPECT_NE(out.find("following run feedforward-s3"), std::string::npos) << out;
  EXPECT_NE(out.find(std::to_string(messages) + " messages (0 bad, skipped), run feedforward-s3, 2 generations"),
            std::string::npos)
      << out;
}

}  // namespace
}  // namespace robozoo::view
