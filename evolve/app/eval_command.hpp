#pragma once
#include <CLI/CLI.hpp>

#include <string>

namespace robozoo {

struct EvalOptions {
  int64_t random_seed = 1;
  std::string regime = "feedforward";
  int mutations = 10;
  std::string genome_file;
  std::string save_genome;
  std::string config_file;
  int steps = 0;  // 0: from the configuration
  bool json = false;
};

void add_eval_options(CLI::App& app, EvalOptions& o);
/// Returns the exit status (0 ok, 2 bad input).
int run_eval_command(const EvalOptions& o);

}  // namespace robozoo
