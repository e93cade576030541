// `impulse catalogue`: every scene file of a directory into videos, and the gallery page.
#pragma once
#include "demos/program.h"

#include <string>
#include <vector>

namespace impulse::demos {

// Which scenes of a catalogue this run renders: one shard of N (--shard K/N: every Nth scene in
// name order, from the Kth), and, with --changed-only, only those whose video is missing or older
// than the scene file or the program. --jobs N renders N at once, each in a child process that
// renders `only` one scene file.
struct CatalogueChoice {
  int shard = 1, shards = 1;
  bool changed_only = false;
  int jobs = 1;
  std::string only;                         // a file name: this process is one job of a --jobs run
  std::vector<std::string> child_arguments;  // for each job: this command line, less what chooses scenes
};

// The command line for a job of --jobs: the same options, less those that chose the scenes (this
// process chose) and the progress bar (one a child would interleave with the others').
std::vector<std::string> job_arguments(const std::vector<std::string>& arguments);  // without the program's name

// Renders the chosen scenes of `scenes_directory` into `out_directory` and writes its gallery
// (not as one job of --jobs); the worst exit code.
int render_catalogue(const std::string& scenes_directory, const std::string& out_directory, bool progress,
                     const VideoOverrides& overrides, const CatalogueChoice& choice);

}  // namespace impulse::demos
