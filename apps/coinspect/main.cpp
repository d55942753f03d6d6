// coinspect: cooperative multi-UAV exploration and inspection, simulated.
#include <cstdio>
#include <exception>

#include "coinspect/core/error.h"
#include "coinspect/core/version.h"
#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"coinspect: cooperative multi-UAV exploration and inspection (CARIC, SLEI3D)"};
  app.set_version_flag("--version", coinspect::version());
  app.require_subcommand(1);
  coinspect::app::addScenarioCommand(app);
  coinspect::app::addScoreCommand(app);
  coinspect::app::addDemoCommand(app);
  coinspect::app::addRunCommand(app);
  coinspect::app::addEvalCommand(app);
  coinspect::app::addRenderCommand(app);
  coinspect::app::addReplayCommand(app);
  coinspect::app::addPlotFeaturesCommand(app);
  coinspect::app::addPlotTimelineCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // CLI11 prints the message (or the help) and has its own codes (105 for a failed check, 109
    // for an unknown option, ...); every bad command line is bad input, as the help says: 2.
    return app.exit(error) == 0 ? 0 : 2;
  } catch (const coinspect::app::CommandStatus& done) {
    return done.status;
  } catch (const coinspect::InputError& error) {
    std::fprintf(stderr, "coinspect: error: %s\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "coinspect: failed: %s\n", error.what());
    return 1;
  }
  return 0;
}
