#include "commands/bench.hpp"

#include <algorithm>
#include <ostream>
#include <stdexcept>

#include "bench/plots.hpp"
#include "bench/report.hpp"
#include "output/plots.hpp"
#include "output/terminal_text.hpp"
#include "validation/checks.hpp"

namespace mortar::harness {

int run_bench_command(const BenchOptions& options, std::ostream& out, std::ostream& err) {
  const BenchResult r = run_bench(options, err);
  const std::string dir = options.out_dir;
  write_rows_csv(dir + "/bench.csv", r);
  write_references_csv(dir + "/reference.csv", r);
  write_text(dir + "/stability.md", stability_list(r));
  const std::string summary = bench_summary(r);
  write_text(dir + "/summary.md", summary);
  out << terminal_text(summary, options.wide);
  if (options.plots) {
    if (!gnuplot_available()) {
      err << "bench: gnuplot is not on the PATH: wrote the chart scripts only\n";
      write_bench_plot_scripts(dir, r);
    } else {
      for (const std::string& script : write_bench_plot_scripts(dir, r)) {
        std::string message;
        if (!run_gnuplot(dir, script, message)) {
          err << "bench: gnuplot failed on " << script << ":\n" << message;
          return 1;
        }
      }
    }
  }
  const std::string wrote = "bench: wrote " + dir + "/bench.csv, reference.csv, stability.md, summary.md" +
                            (options.plots ? ", work_precision{,_all}.{png,svg}, stability_map.{png,svg}" : "") + "\n";
  out << terminal_text(wrote, options.wide);
  const ReferenceSpread spread = reference_spread(r);
  if (!(spread.traction < kReferenceRequired && spread.energy < kReferenceRequired)) {
    err << "masonry-joint bench: the reference moved by " << format_number(std::max(spread.traction, spread.energy), 2)
        << " when tightened (reference.csv); the study needs less than " << format_number(kReferenceRequired, 2)
        << " to tell accurate runs from inaccurate ones\n";
    return 1;
  }
  return 0;
}

int run_throughput_command(const ThroughputOptions& options, std::ostream& out, std::ostream& err) {
  try {
    out << terminal_text(throughput_report(run_throughput(options, err)), options.wide);
  } catch (const std::runtime_error& e) {
    err << "masonry-joint " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace mortar::harness
