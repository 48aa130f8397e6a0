// littermap: one executable, one subcommand per stage (DESIGN.md, "The command line").
// Exit codes: 0 success, 1 usage error, 2 bad input data, 3 internal error, 4 environment
// (disk full, permission denied, device gone, out of memory); core/failure.hpp decides which.

#include <csignal>
#include <cstdio>
#include <exception>

#include <malloc.h>

#include <CLI/CLI.hpp>

#include "cli/cli_context.hpp"
#include "cli/command_names.hpp"
#include "core/failure.hpp"
#include "littermap_version.hpp"

namespace {

constexpr int kExitUsage = 1;

int Fail(littermap::cli::CliContext& context, int code, const char* what) {
  context.FinishProgress();
  std::fprintf(stderr, "littermap: error: %s\n", what);
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  // The pipelines allocate and free buffers of up to megabytes for every scan or frame (KD-trees,
  // correlative grids, images). glibc serves those from fresh mappings and trims its heap when
  // they are freed, so each one faults its pages in again: keep them in the heap for reuse
  // (reconstructing freiburg-campus: half the system time, the same peak memory).
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  // A file-size limit (ulimit -f) then fails the write with EFBIG, which every writer reports
  // like a full disk, instead of killing the process mid-file.
  std::signal(SIGXFSZ, SIG_IGN);
  using littermap::cli::CliContext;
  CLI::App app{"littermap: litter distribution maps from a park robot's sensor logs"};
  app.set_version_flag("--version", "littermap " LITTERMAP_VERSION);
  app.require_subcommand(1);

  CliContext context;
  app.add_flag("-q,--quiet", context.quiet, "No progress output on stderr");
  littermap::cli::RegisterInfoCommand(app, context);
  littermap::cli::RegisterConvertCommand(app, context);
  littermap::cli::RegisterImportCommands(app, context);
  littermap::cli::RegisterSimulateCommand(app, context);
  littermap::cli::RegisterCaptureCommand(app, context);
  littermap::cli::RegisterReconstructCommand(app, context);
  littermap::cli::RegisterDetectCommand(app, context);
  littermap::cli::RegisterTrainCommands(app, context);
  littermap::cli::RegisterEvalCommands(app, context);
  littermap::cli::RegisterEvalDetectionsCommand(app, context);
  littermap::cli::RegisterEvalMapCommand(app, context);
  littermap::cli::RegisterEvalSettleCommand(app, context);
  littermap::cli::RegisterEvalSegmentationCommand(app, context);
  littermap::cli::RegisterEvalRelationsCommand(app, context);
  littermap::cli::RegisterSiteCommands(app, context);
  littermap::cli::RegisterIngestCommand(app, context);
  littermap::cli::RegisterHeatmapCommand(app, context);
  littermap::cli::RegisterReportCommand(app, context);
  littermap::cli::RegisterSurveyCommand(app, context);

  try {
    littermap::cli::CheckCommandNames(app, argc, argv);
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, version or the usage error
    return code == 0 ? 0 : kExitUsage;
  } catch (const std::exception& e) {  // an input checked at the door (cli/option_checks.hpp)
    return Fail(context, static_cast<int>(littermap::KindOf(e)), e.what());
  }

  try {
    if (context.run) context.run();
    context.FinishProgress();
    return 0;
  } catch (const std::bad_alloc&) {
    return Fail(context, static_cast<int>(littermap::ErrorKind::kEnvironment), "out of memory");
  } catch (const std::exception& e) {
    return Fail(context, static_cast<int>(littermap::KindOf(e)), e.what());
  }
}
