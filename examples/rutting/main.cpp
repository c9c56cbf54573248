// vrut-rutting: the virtual wheel-tracking test of an asphalt mixture, from
// its gradation and binder properties to the rut depth and dynamic stability.
// The test itself, its options and its outputs are the library's application
// layer (include/vrut/app/), which the Python module runs too; this program
// adds the command line, --resume and MPI.
#include <vrut/app/cli.hpp>
#include <vrut/app/ranks.hpp>
#include <vrut/app/rutting_2d.hpp>
#include <vrut/app/rutting_3d.hpp>
#include <vrut/app/rutting_options.hpp>

#include <vrut/io/checkpoint.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace vrut::app;
  ranks::Session session(argc, argv);  // mpirun -np K: K ranks share the seeds of an ensemble
  RunOptions given;
  std::string resume;
  CLI::App app("vrut-rutting: virtual wheel-tracking (rutting) test of an asphalt mixture, DEM with Burger's mastic");
  add_run_options(app, given);
  app.add_option("--resume", resume, "go on with the run whose checkpoint is in this folder, with its options")
      ->group("Runs")->configurable(false);
  if (const int code = cli::parse(app, argc, argv); code >= 0) return code;
  given.io.images = image_cli::given_images(given.io);
  given.width_given = app.count("--width-mm") > 0;
  given.voids_given = app.count("--air-voids") > 0;
  given.seed_given = app.count("--seed") > 0;

  const int code = cli::guarded([&] {
    namespace fs = std::filesystem;
    std::optional<vrut::CheckpointFile> checkpoint;
    RunOptions o = given;
    std::string config_text = app.config_to_str(true, true);
    // Each rank checkpoints its own specimens, and resumes them with as many ranks.
    const std::string checkpoint_name = ranks::checkpoint_name(session.rank(), session.size());
    if (!resume.empty()) {
      const fs::path file = fs::path(resume) / checkpoint_name;
      if (!fs::exists(file)) {
        // A run of another rank count: say how to go on with it.
        if (const int ranks_then = ranks::checkpoint_ranks_in(resume); ranks_then > 0)
          throw std::invalid_argument(resume + " holds the checkpoints of a run on " + std::to_string(ranks_then) +
                                      " rank(s), and this is " + std::to_string(session.size()) +
                                      ": go on with it as " + ranks::resume_command(ranks_then, resume));
        throw std::invalid_argument("no checkpoint in " + resume + " (" + file.string() +
                                    "): a run writes one on Ctrl-C, or every --checkpoint-every seconds" +
                                    (session.size() > 1 ? "; resume with as many ranks as the run had" : ""));
      }
      checkpoint = vrut::CheckpointFile::resume(file, given.checkpoint_every);
      o = options_to_resume(app, given, *checkpoint);
      checkpoint->set_interval(o.checkpoint_every);
      o.out = resume;
      config_text = checkpoint->header().at("config_with_help").get<std::string>();
    } else {
      // An unfinished run's checkpoint, of this rank count or another, is never overwritten unasked.
      if (const int ranks_then = ranks::checkpoint_ranks_in(given.out); ranks_then > 0 && !given.force)
        throw std::invalid_argument("'" + given.out + "' holds the checkpoint of an unfinished run: go on with it "
                                    "with " + ranks::resume_command(ranks_then, given.out) +
                                    ", or start again with --force");
      // The default folder, where no --out was named (on the command line or
      // in a config file), holds the last run's results: a new run replaces
      // them, so that the main job runs again as it is. A folder the user
      // named is refused unless --force (OutputDir).
      if (app.count("--out") == 0) o.force = true;
      nlohmann::json header;
      header["argv"] = std::vector<std::string>(argv + 1, argv + argc);
      header["config"] = app.config_to_str(true, false);
      header["config_with_help"] = config_text;
      checkpoint.emplace(fs::path(given.out) / checkpoint_name, given.checkpoint_every, header);
    }
    if (o.out.empty()) throw std::invalid_argument("--out: the output folder, not empty");
    const vrut::app::RuttingOutcome outcome = o.dim == 3 ? vrut::app::run_rutting_3d(o, &*checkpoint, config_text, session)
                                                         : vrut::app::run_rutting_2d(o, &*checkpoint, config_text, session);
    return outcome.exit_code;
  });
  // A rank that failed takes the others down rather than leave them waiting.
  if (session.size() > 1 && code != 0 && code < 128) session.abort(code);
  return code;
}
