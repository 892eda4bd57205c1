// robozoo-evolve: CPPN-NEAT evolution of complete robots, published over LCM
// and logged (issue 4); `robozoo-evolve eval` grows and simulates one genome.
#include <unistd.h>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include "evolve/app/eval_command.hpp"
#include "evolve/app/run_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "robozoo-evolve: evolve complete robots (body, joints, sensors, CTRNN brain) with CPPN-NEAT,\n"
      "selected for directed displacement in ODE. Every event goes to an LCM log (and, with --lcm-url,\n"
      "to the LCM bus); a checkpoint after every generation lets --resume continue a killed run.\n"
      "Precedence of settings: defaults < --preset < --config FILE < command-line flags."};
  app.set_version_flag("--version", ROBOZOO_VERSION);
  robozoo::RunOptions run;
  robozoo::add_run_options(app, run);
  robozoo::EvalOptions eval;
  CLI::App* eval_cmd = app.add_subcommand(
      "eval", "Grow and simulate one genome (random from a seed, or from a genome JSON file), print "
              "its morphology, outcome and fitness");
  robozoo::add_eval_options(*eval_cmd, eval);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "robozoo-evolve: " << e.what() << " (see --help)\n";
    return 2;
  }
  if (eval_cmd->parsed()) return robozoo::run_eval_command(eval);
  return robozoo::run_run_command(app, run);
}
