// cadmedial command line. Exit codes: see cadmedial/errors.hpp and the README.
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>
#include <Standard_Failure.hxx>

#include "cadmedial/errors.hpp"
#include "run_command.hpp"
#include "sample_command.hpp"

int main(int argc, char** argv) {
  using namespace cadmedial;
  CLI::App app{"cadmedial: medial axes of CAD solids"};
  app.require_subcommand(1);

  SampleCommandOptions sample;
  CLI::App* sampleCmd = app.add_subcommand("sample", "Sample a B-rep (triplets, umbrellas) and write PLY files");
  sampleCmd->add_option("model", sample.model, "STEP/IGES/BREP file")->required();
  sampleCmd->add_option("-o,--output", sample.outDir, "Output directory")->required();
  sampleCmd->add_option("--spacing", sample.spacing, "Target sample spacing h in model units (default: diagonal/40)")
      ->check(CLI::PositiveNumber);

  RunCommandOptions run;
  CLI::App* runCmd = app.add_subcommand("run", "Compute the inner medial axis (CAD_MEDIAL) of every solid");
  runCmd->add_option("model", run.model, "STEP/IGES/BREP file")->required();
  runCmd->add_option("-o,--output", run.outDir, "Output directory")->required();
  runCmd->add_option("--spacing", run.spacing, "Target sample spacing h in model units (default: diagonal/40)")
      ->check(CLI::PositiveNumber);
  runCmd->add_option("--theta", run.params.thetaDeg, "Angle condition threshold in degrees (default 5)")
      ->check(CLI::Range(0.0, 89.0));
  runCmd->add_option("--rho", run.params.rho, "Ratio condition threshold (default 8)")->check(CLI::PositiveNumber);
  bool noOracle = false;
  runCmd->add_flag("--no-oracle", noOracle,
                   "Skip the check of the inner/outer walk against OCCT's exact classifier (faster)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }

  try {
    if (*sampleCmd) return runSampleCommand(sample);
    if (*runCmd) {
      run.checkWithOracle = !noOracle;
      return runRunCommand(run);
    }
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return e.code();
  } catch (const Standard_Failure& e) {
    std::cerr << "error: geometry kernel failure: " << e.GetMessageString() << "\n";
    return kExitProcessingFailed;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitProcessingFailed;
  }
  return kExitUsage;
}
