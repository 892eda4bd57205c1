#pragma once
#include <CLI/CLI.hpp>

#include <string>

namespace robozoo {

struct RunOptions {
  std::string regime = "feedforward";
  int64_t seed = 1;
  int population = 150;
  int generations = 500;
  int steps = 2500;
  int workers = 0;  // 0: number of cores
  std::string config_file;
  std::string preset;
  std::string log_path;
  std::string lcm_url;
  int pose_every = 4;
  bool publish_all = false;
  bool resume = false;
  std::string run_id;
  double job_timeout = 600.0;
  bool quiet = false;
  bool print_config = false;
};

void add_run_options(CLI::App& app, RunOptions& o);
/// Runs (or resumes) an evolution; returns the process exit status
/// (0 done, 2 bad configuration or unusable files, 1 failure during the run).
int run_run_command(const CLI::App& app, const RunOptions& o);

}  // namespace robozoo
