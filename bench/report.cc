#include "bench/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "bench/format.h"
#include "plot/chart.h"

namespace billiard::bench {

namespace {

const MethodSummary* Find(const BenchmarkResult& r, const std::string& method,
                          const std::string& kind) {
  for (const MethodSummary& s : r.summaries) {
    if (s.method.Name() == method && s.kind == kind) return &s;
  }
  return nullptr;
}

void WriteCsv(const BenchmarkResult& r, const std::string& path) {
  std::ofstream out = OpenForWriting(path);
  out.precision(10);
  out << "method,scene,group,kind,ok,wall_us,steps,rhs_evals,error_self_m,error_integral_m,"
         "failure\n";
  for (const MethodRun& run : r.runs) {
    std::string failure = run.failure;
    std::replace(failure.begin(), failure.end(), ',', ';');
    out << run.method << ',' << run.scene << ',' << run.group << ',' << run.kind << ',' << run.ok
        << ',' << run.wall_us << ',' << run.steps << ',' << run.rhs_evals << ',' << run.error_self_m
        << ',' << run.error_integral_m << ',' << failure << '\n';
  }
  if (!out) throw std::runtime_error("writing '" + path + "' failed");
}

void SummaryTable(std::ostream& md, const BenchmarkResult& r, const std::string& kind) {
  md << "| method | median us | p95 us | median steps | median rhs | p95 error, same model "
        "converged [m] | median / p95 / max error, integral converged [m] | failed |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const MethodSummary& s : r.summaries) {
    if (s.kind != kind) continue;
    md << "| " << s.method.Name() << " | " << Fixed(s.median_us, 2) << " | " << Fixed(s.p95_us, 2)
       << " | " << Fixed(s.median_steps, 0) << " | " << Fixed(s.median_rhs_evals, 0) << " | "
       << Sci(s.p95_error_self_m) << " | " << Sci(s.median_error_integral_m) << " / "
       << Sci(s.p95_error_integral_m) << " / " << Sci(s.max_error_integral_m) << " | " << s.failures
       << "/" << s.runs << " |\n";
  }
}

// The targets, stated as met or missed with the numbers.
void Targets(std::ostream& md, const BenchmarkResult& r) {
  md << "## Targets\n\n";
  const MethodSummary* approx = nullptr;  // cheapest approx/rodas4 with p95 self error < 1e-6
  for (const MethodSummary& s : r.summaries) {
    if (s.kind != "all" || s.method.Family() != "approx/rodas4" || s.failures > 0) continue;
    if (s.p95_error_self_m < 1e-6 && (!approx || s.median_us < approx->median_us)) approx = &s;
  }
  if (approx) {
    const bool met = approx->median_us < 100.0;
    md << "- Approx model, 8 s shot, endpoint error < 1e-6 m (p95 against the approx model "
          "converged): "
       << approx->method.Name() << " takes a median of " << Fixed(approx->median_us, 1)
       << " us (p95 " << Fixed(approx->p95_us, 1)
       << " us): " << (met ? "**met** (target 100 us)." : "**missed** (target 100 us).") << "\n";
  } else {
    md << "- Approx model below 1e-6 m: **missed**, no tolerance reached it on every scene.\n";
  }
  if (const MethodSummary* cf = Find(r, "closed-form", "all")) {
    md << "- Closed form: median " << Fixed(cf->median_us, 3) << " us, p95 " << Fixed(cf->p95_us, 3)
       << " us: " << (cf->median_us < 1.0 ? "**met**" : "**missed**") << " (target 1 us).\n";
  }
  md << "- Integral model as the reference: " << r.integral_reference.Name()
     << ", quadrature error estimate " << Sci(r.integral_reference_quadrature_error)
     << " (on |T| and |Ms|).\n\n";
}

// Our default method against Odeint, CVODE and the floor on Figs. 6-10, with issue 16's targets.
void PeersTable(std::ostream& md, const PeerComparison& peers) {
  double max_shift = 0.0;
  for (const FigureComparison& f : peers.figures) {
    max_shift = std::max(max_shift, f.rest_switch_shift_m);
  }
  md << "## Against the peers\n\n"
     << "The approx model on Figs. 6-10 to 8 s, every endpoint within "
     << Sci(kPeerEndpointAccuracy) << " m of its converged one, on one core (median of "
     << kPeerTiming.batches
     << " batches, the four interleaved). Ours: `physics::Simulate` at its defaults (tolerance "
     << "1e-6, rest switch on), the call `billiard simulate --json` times, as it times it. "
     << "Boost.Odeint's rosenbrock4 (Ahnert & Mulansky 2011) and SUNDIALS CVODE's BDF with the "
     << "dense solver (Hindmarsh et al. 2005) run the same "
     << "equations with our analytic Jacobian and our error weights, at the loosest tolerance of "
     << "1e-3 .. 1e-10 (factors of about 3) that reaches the accuracy, against the regularized "
     << "equations converged: they have no rest switch and integrate the stopped ball's "
     << "precession to 8 s (Figs. 9, 10; the two converged endpoints, with and without the rest "
     << "switch, are up to " << Sci(max_shift) << " m apart). A tolerance of 1e-3, the sweep's "
     << "loosest, may not be the loosest that would do: above 3e-4 only the position weight "
     << "loosens, velocities and spins being capped at 10 eps a. The floor: one right-hand side "
     << "with its Jacobian, the stage matrix inverted and six solves by RODAS4's own code (its "
     << "per-step arithmetic without its five further right-hand sides), timed in a tight loop "
     << "over states along the figure, times the fewest accepted steps RODAS4 takes at any "
     << "tolerance of the sweep that reaches the accuracy (`bench/peer_comparison.h`). A whole "
     << "RODAS4 step is timed on the same states: at that cost per accepted step, with nothing "
     << "else (no rejected step, error control, dense output or event search), ours over the "
     << "floor would be the last column, the per-step factor times the steps at the default over "
     << "the fewest.\n\n"
     << "| figure | ours us (steps) | Odeint us (tol, steps) | CVODE us (tol, steps) | floor us "
        "(steps x us/step) | ours/Odeint | ours/CVODE | ours/floor | RODAS4 step us | "
        "ours/floor from the step's arithmetic |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n";
  const auto peer_cell = [](const PeerOnFigure& peer) {
    if (!peer.found) return std::string("not reached");
    return Fixed(peer.wall_us, 1) + " (" + Sci(peer.tolerance) + ", " +
           std::to_string(peer.run.steps) + ")";
  };
  const auto ratio_cell = [](double ratio) { return ratio > 0.0 ? Fixed(ratio, 2) : "-"; };
  int odeint_met = 0, floor_met = 0;
  for (const FigureComparison& f : peers.figures) {
    const double over_odeint = Ratio(f.ours.wall_us, f.odeint.wall_us);
    const double over_floor = Ratio(f.ours.wall_us, f.floor.wall_us);
    odeint_met += f.odeint.found && over_odeint <= kTargetOursOverOdeint;
    floor_met += over_floor <= kTargetOursOverFloor;
    md << "| " << f.scene << " | " << Fixed(f.ours.wall_us, 1) << " (" << f.ours.stats.steps
       << ") | " << peer_cell(f.odeint) << " | " << peer_cell(f.cvode) << " | "
       << Fixed(f.floor.wall_us, 1) << " (" << f.floor.steps << " x " << Fixed(f.floor.step_us, 3)
       << ") | " << ratio_cell(over_odeint) << " | "
       << ratio_cell(Ratio(f.ours.wall_us, f.cvode.wall_us)) << " | " << ratio_cell(over_floor)
       << " | " << Fixed(f.floor.rodas4_step_us, 3) << " | "
       << ratio_cell(OursOverFloorFromArithmetic(f)) << " |\n";
  }
  const int n = static_cast<int>(peers.figures.size());
  const auto verdict = [n](int met) { return met == n ? "**met**" : "**not met**"; };
  md << "\n- Ours at most " << Fixed(kTargetOursOverOdeint, 1) << " x Odeint's time on each "
     << "figure: " << verdict(odeint_met) << " (" << odeint_met << "/" << n << ").\n"
     << "- Ours within " << Fixed(kTargetOursOverFloor, 0)
     << " x the floor on each figure: " << verdict(floor_met) << " (" << floor_met << "/" << n
     << ").\n\n";
}

void WriteMarkdown(const BenchmarkResult& r, const std::string& path) {
  std::ofstream md = OpenForWriting(path);
  md << "# Speed against error\n\n"
     << "Generated by `billiard bench` (" << r.params << " parameters, " << r.scenes.size()
     << " scenes: the five Figs. 6-10 states, " << ScenesOfGroup(r.scenes, "random").size()
     << " seeded random cue shots, the hard cases; " << r.methods.size() << " methods; "
     << Fixed(r.wall_s, 0) << " s). Times are wall-clock per shot on one core (cheap runs "
     << "repeated in batches, the median of the batch means). Errors are endpoint distances at "
     << "t_end (8 s; 60 s for one hard case) from " << r.approx_reference.Name()
     << " (the approx model converged) and from " << r.integral_reference.Name()
     << " (the integral model converged).\n\n";
  Targets(md, r);
  md << "## All scenes\n\n";
  SummaryTable(md, r, "all");
  md << "\n## Rolling from the start, no side spin\n\n";
  SummaryTable(md, r, "rolling");
  md << "\n## Sliding, no side spin (stun, follow, draw)\n\n";
  SummaryTable(md, r, "sliding");
  md << "\n## With side spin\n\n";
  SummaryTable(md, r, "side-spin");
  md << "\n## Figures 6-10 (time us / error against the integral model converged, m)\n\n| method |";
  for (const Scene& s : r.scenes) {
    if (s.group == "figure") md << ' ' << s.name << " |";
  }
  md << "\n|---|---|---|---|---|---|\n";
  for (const Method& m : r.methods) {
    md << "| " << m.Name() << " |";
    for (const MethodRun& run : r.runs) {
      if (run.method != m.Name() || run.group != "figure") continue;
      md << ' ' << (run.ok ? Fixed(run.wall_us, 1) + " / " + Sci(run.error_integral_m) : "failed")
         << " |";
    }
    md << '\n';
  }
  md << "\nFailures, if any, are runs that exceeded the integrator's step budget; see "
        "results.csv.\n";
  md << '\n';
  PeersTable(md, r.peers);
  md << "## Many shots on all cores\n\n" << BatchScalingMarkdown(r.batch_scaling);
  if (!md) throw std::runtime_error("writing '" + path + "' failed");
}

// Log-log chart (plot/chart.h): x = median wall time, y = p95 error against the integral
// model, all scenes; one line per method family, each point labelled with its tolerances.
void WritePlot(const BenchmarkResult& r, const std::string& path) {
  plot::Chart chart;
  chart.title = "Speed against error, " + std::to_string(r.scenes.size()) + " scenes, " +
                r.params + " parameters";
  chart.x_label = "median wall time per shot [us]";
  chart.y_label = "p95 endpoint error vs integral converged [m]";
  std::map<std::string, std::vector<const MethodSummary*>> families;
  for (const MethodSummary& s : r.summaries) {
    if (s.kind != "all" || s.runs == s.failures) continue;
    families[s.method.Family()].push_back(&s);
  }
  for (auto& [family, points] : families) {
    std::sort(points.begin(), points.end(),
              [](auto* a, auto* b) { return a->median_us < b->median_us; });
    plot::ChartSeries series{family, {}};
    for (const MethodSummary* s : points) {
      // The name past the family: "tol=1e-06", "tol=1e-05/quad=1e-03"; none for the closed form.
      const std::string name = s->method.Name();
      const std::string label = name.size() > family.size() ? name.substr(family.size() + 1) : "";
      series.points.push_back({s->median_us, s->p95_error_integral_m, label});
    }
    chart.series.push_back(series);
  }
  plot::DrawChart(chart, path);
}

}  // namespace

nlohmann::json ModelChoiceTable(const BenchmarkResult& r) {
  nlohmann::json table = {
      {"error_metric", "p95 endpoint distance from the integral model converged [m]"},
      {"time_metric", "median wall time per shot on one core [us]"},
      {"params", r.params},
      {"kinds", nlohmann::json::object()}};
  for (const std::string& kind : kSceneKinds) {
    if (kind == "all") continue;
    nlohmann::json rows = nlohmann::json::array();
    for (const MethodSummary& s : r.summaries) {
      if (s.kind != kind || s.failures > 0 || s.runs == 0) continue;
      rows.push_back({{"model", physics::ModelName(s.method.model)},
                      {"integrator", physics::IntegratorName(s.method.integrator)},
                      {"tolerance", s.method.tolerance},
                      {"quadrature_tolerance", s.method.quadrature_tolerance},
                      {"median_us", s.median_us},
                      {"p95_error_m", s.p95_error_integral_m}});
    }
    table["kinds"][kind] = rows;
  }
  return table;
}

nlohmann::json SummaryJson(const BenchmarkResult& r, const std::string& dir) {
  nlohmann::json methods = nlohmann::json::array();
  for (const MethodSummary& s : r.summaries) {
    if (s.kind != "all") continue;
    methods.push_back({{"method", s.method.Name()},
                       {"median_us", s.median_us},
                       {"p95_us", s.p95_us},
                       {"p95_error_self_m", s.p95_error_self_m},
                       {"p95_error_integral_m", s.p95_error_integral_m},
                       {"failures", s.failures}});
  }
  nlohmann::json summary = {{"out", dir},
                            {"scenes", r.scenes.size()},
                            {"runs", r.runs.size()},
                            {"wall_s", r.wall_s},
                            {"methods", methods}};
  summary["peers"] = PeerComparisonJson(r.peers);
  summary["batch_scaling"] = BatchScalingJson(r.batch_scaling);
  return summary;
}

void WriteReport(const BenchmarkResult& result, const std::string& dir) {
  std::filesystem::create_directories(dir);
  WriteCsv(result, dir + "/results.csv");
  WriteMarkdown(result, dir + "/report.md");
  WritePlot(result, dir + "/speed_vs_error.png");
  std::ofstream choice = OpenForWriting(dir + "/model_choice.json");
  choice << ModelChoiceTable(result).dump(2) << '\n';
}

}  // namespace billiard::bench
