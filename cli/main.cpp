// cadmedial command line. Exit codes: see cadmedial/errors.hpp and the README.
#include <exception>
#include <iostream>
#include <string>
#include <system_error>

#include <CLI/CLI.hpp>
#include <Standard_Failure.hxx>

#include "batch_runner.hpp"
#include "cadmedial/errors.hpp"
#include "eval_command.hpp"
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
  const char* gradedSpacingHelp =
      "The sample spacing is graded within each face, fine only where curvature or a thin wall needs it (e.g. at a "
      "cone's apex): the default. --uniform-spacing samples each face at one spacing, the finest it needs anywhere "
      "(the behaviour before 2026-12-02)";
  sampleCmd->add_flag("--graded-spacing,!--uniform-spacing", sample.gradedSpacing, gradedSpacingHelp);

  RunCommandOptions run;
  CLI::App* runCmd = app.add_subcommand(
      "run", "Compute the inner medial axis (CAD_MEDIAL) of every solid, or MEDIAL on a point cloud / mesh");
  runCmd->add_option("model", run.model,
                     "STEP/IGES/BREP file, point cloud (.xyz .pts .ply) or triangle mesh (.stl .obj .off .ply)")
      ->required();
  runCmd->add_option("-o,--output", run.outDir, "Output directory")->required();
  runCmd->add_option("--spacing", run.spacing, "Target sample spacing h in model units (default: diagonal/40)")
      ->check(CLI::PositiveNumber);
  runCmd->add_flag("--graded-spacing,!--uniform-spacing", run.gradedSpacing, gradedSpacingHelp);
  runCmd->add_option("--theta", run.params.thetaDeg,
                     "Angle condition threshold in degrees (default 5; 22.5 = pi/8 for point clouds and meshes)")
      ->check(CLI::Range(0.0, 89.0));
  runCmd->add_option("--rho", run.params.rho, "Ratio condition threshold (default 8)")->check(CLI::PositiveNumber);
  bool keepTopologyArtefacts = false;
  runCmd->add_flag("--keep-topology-artefacts", keepTopologyArtefacts,
                   "Neither close one-facet or short holes nor drop one-point, forced-only, sub-resolution or nested islands of "
                   "the inner axis "
                   "(to see the raw Angle/Ratio selection; ARCHITECTURE.md)");
  bool keepFringe = false;
  runCmd->add_flag("--keep-fringe", keepFringe,
                   "Keep the fringe of Voronoi facets around 1-D parts of the axis (fillet centre curves, cylinder "
                   "axes) instead of collapsing it (ARCHITECTURE.md \"Two contacts\")");
  bool seedAngleTest = false;
  runCmd->add_flag("--seed-angle-test", seedAngleTest,
                   "At concave-edge samples, judge the Angle condition against every umbrella normal, as seed 002 "
                   "does, not only the faces an edge heads over (ARCHITECTURE.md)");
  runCmd->add_flag("--pair-mesh", run.pairMesh,
                   "Also build the pair-mesh (tetrahedra between the inner Voronoi diagram and the boundary): "
                   "pairmesh.vtu, pairmesh.node/.ele, iso_<t>.ply");
  runCmd->add_option("--iso", run.isoValues, "Iso-parametric surfaces written with --pair-mesh, t in [0, 1] (default 0.5)")
      ->check(CLI::Range(0.0, 1.0));
  bool noOracle = false;
  runCmd->add_flag("--no-oracle", noOracle,
                   "Skip the check of the inner/outer walk against OCCT's exact classifier (faster)");

  BatchOptions batch;
  CLI::App* batchCmd = app.add_subcommand(
      "batch", "Run `run` over many files, each in its own process; one record per file in OUTDIR/results.jsonl");
  batchCmd->add_option("inputs", batch.inputs, "Model files, folders (recursive) or manifests (*.txt, *.lst, @FILE)")
      ->required();
  batchCmd->add_option("-o,--output", batch.outDir, "Output directory")->required();
  batchCmd->add_option("-j,--jobs", batch.jobs, "Files processed at once (default: number of cores)")
      ->check(CLI::PositiveNumber);
  batchCmd->add_option("--timeout", batch.timeoutSeconds, "Seconds per file before it is killed (default: none)")
      ->check(CLI::PositiveNumber);
  batchCmd->add_option("--max-memory", batch.maxMemoryGiB, "Address-space limit per file in GiB (default: none)")
      ->check(CLI::PositiveNumber);
  batchCmd->add_flag("--resume", batch.resume, "Skip files whose last record is ok and whose outputs exist");
  batchCmd->add_flag("--eval", batch.eval, "Also run `cadmedial eval` on each file's outputs");
  // Passed on to `cadmedial run` as given.
  batchCmd->add_option("--spacing", "As for run")->check(CLI::PositiveNumber);
  batchCmd->add_flag("--graded-spacing", "As for run (the default)")
      ->excludes(batchCmd->add_flag("--uniform-spacing", "As for run"));
  batchCmd->add_option("--theta", "As for run")->check(CLI::Range(0.0, 89.0));
  batchCmd->add_option("--rho", "As for run")->check(CLI::PositiveNumber);
  batchCmd->add_flag("--no-oracle", "As for run");
  batchCmd->add_flag("--pair-mesh", "As for run");

  EvalCommandOptions eval;
  CLI::App* evalCmd =
      app.add_subcommand("eval", "Measure the medial axes written by `run` against the exact B-rep (eval.json per solid)");
  evalCmd->add_option("model", eval.model, "The STEP/IGES/BREP file given to `run`")->required();
  evalCmd->add_option("outdir", eval.outDir, "The output directory of `run`");
  evalCmd->add_option("-o,--output", eval.outDir, "Same as OUTDIR");
  evalCmd->add_option("--tolerance", eval.tolerance, "Tolerance as a fraction of the bounding-box diagonal (default 0.005)")
      ->check(CLI::Range(1e-9, 0.999999));
  evalCmd->add_flag("--strict", eval.strict, "Exit with code 1 when a solid fails a threshold");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }

  try {
    if (*sampleCmd) return runSampleCommand(sample);
    if (*evalCmd) {
      if (eval.outDir.empty()) {
        std::cerr << "error: eval needs the output directory of `run` (cadmedial eval MODEL OUTDIR)\n";
        return kExitUsage;
      }
      return runEvalCommand(eval);
    }
    if (*runCmd) {
      run.checkWithOracle = !noOracle;
      run.thetaGiven = runCmd->get_option("--theta")->count() > 0;
      if (seedAngleTest) run.params.oneSidedConcaveEdges = false;
      if (keepFringe) run.params.thinFringe = false;
      if (keepTopologyArtefacts) {
        run.params.fillSingleFacetHoles = false;
        run.params.fillShortHoles = false;
        run.params.islandRadiusFraction = 0;
        run.params.dropPointIslands = false;
        run.params.dropForcedOnlyIslands = false;
        run.params.dropNestedIslands = false;
      }
      return runRunCommand(run);
    }
    if (*batchCmd) {
      for (const char* name : {"--spacing", "--theta", "--rho"})
        if (const CLI::Option* o = batchCmd->get_option(name); o->count() > 0)
          batch.runArguments.insert(batch.runArguments.end(), {name, o->as<std::string>()});
      for (const char* flag : {"--no-oracle", "--pair-mesh", "--graded-spacing", "--uniform-spacing"})
        if (batchCmd->get_option(flag)->count() > 0) batch.runArguments.push_back(flag);
      return runBatchCommand(batch);
    }
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return e.code();
  } catch (const Standard_Failure& e) {
    std::cerr << "error: geometry kernel failure: " << e.GetMessageString() << "\n";
    return kExitProcessingFailed;
  } catch (const std::exception& e) {
    // A thread that cannot be started (EAGAIN from pthread_create: std::async
    // says so with a system_error, TBB with this message) means no address
    // space for its stack, i.e. a memory limit (ulimit -v, batch --max-memory).
    const std::string what = e.what();
    const auto* system = dynamic_cast<const std::system_error*>(&e);
    if (what.find("pthread_create") != std::string::npos ||
        (system && system->code() == std::errc::resource_unavailable_try_again))
      std::cerr << "error: out of memory: cannot start a thread (" << what << ")\n";
    else
      std::cerr << "error: " << what << "\n";
    return kExitProcessingFailed;
  }
  return kExitUsage;
}
