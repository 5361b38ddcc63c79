// cadmedial command line. Exit codes: see cadmedial/errors.hpp and the README.
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>
#include <Standard_Failure.hxx>

#include "cadmedial/errors.hpp"
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

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }

  try {
    if (*sampleCmd) return runSampleCommand(sample);
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
