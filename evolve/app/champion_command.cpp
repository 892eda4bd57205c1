#include "evolve/app/champion_command.hpp"

#include <iostream>

#include "evolve/run/champion_log.hpp"
#include "evolve/messages/build.hpp"
#include "util/exit_status.hpp"

namespace robozoo {

void add_champion_options(CLI::App& app, ChampionOptions& o) {
  app.add_option("RESULT", o.results_file, "a compact result (<run>.results.json, robozoo-experiment's results/)")
      ->required();
  app.add_option("--log", o.log_path, "the log to write")->required();
  app.add_flag("--force", o.force,
               "use a result written by another robozoo version (its champion must still "
               "evaluate to the committed fitness)");
}

int run_champion_command(const ChampionOptions& o) {
  RunResults r;
  try {
    r = read_run_results(o.results_file);
  } catch (const std::exception& e) {
    std::cerr << "robozoo-evolve champion: " << e.what() << "\n";
    return 2;
  }
  if (r.run.software_version != software_version() && !o.force) {
    std::cerr << "robozoo-evolve champion: " << o.results_file << ": written by robozoo " << r.run.software_version
              << ", this is robozoo " << software_version()
              << "; use that version, or --force (the champion must still evaluate to its committed fitness)\n";
    return 2;
  }
  return exit_status_of("robozoo-evolve champion", [&] {
    const ChampionLogInfo info = write_champion_log(r, o.log_path);
    std::cerr << "robozoo-evolve champion: genome " << info.genome_id << " (best of run " << r.run.run_id
              << ", generation " << info.generation << ", fitness " << info.fitness << "): " << info.poses
              << " poses in " << o.log_path << "\n";
    return 0;
  });
}

}  // namespace robozoo
