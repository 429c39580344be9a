// sph_soil_refine_map: the kernel-gradient error map and instability conditions of one split
// (the dynamic-refinement paper's Fig. 1) over a grid of (eps_r, alpha_r), as CSV, and the
// parameters that minimise max(E_a, E_b) among the stable ones, and the push that a split and the
// edge of a refined zone give a soil at rest. See doc/refinement_parameters.rst.
#include "soil_refine_error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace SPHSoil;

namespace {

struct Options {
  int dimension = 2;
  double ra = 1.2, lo = 0.2, hi = 0.8, step = 0.02, tolerance = 1.0e-5;
  std::string csv = "refine_map.csv", json;
};

void usage()
{
  std::puts("usage: sph_soil_refine_map [--dimension 2|3] [--ra R] [--min A] [--max B] [--step S]\n"
            "                           [--tolerance T] [--csv FILE] [--json FILE]\n"
            "Writes E_a (h(x) = h_p), E_b (h(x) = alpha_r h_p) and the instability conditions for\n"
            "d_ij/d_ref = 1.0 and 0.85 over eps_r, alpha_r in [A, B] (default 0.2..0.8, step 0.02,\n"
            "r_a = 1.2, 2D), and reports the stable parameters with the smallest max(E_a, E_b).");
}

bool parse(int argc, char **argv, Options &o)
{
  for (int i = 1; i < argc; i++) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") return usage(), false;
    if (i + 1 >= argc) return std::fprintf(stderr, "option %s needs a value\n", a.c_str()), false;
    const char *v = argv[++i];
    if (a == "--dimension") o.dimension = std::atoi(v);
    else if (a == "--ra") o.ra = std::atof(v);
    else if (a == "--min") o.lo = std::atof(v);
    else if (a == "--max") o.hi = std::atof(v);
    else if (a == "--step") o.step = std::atof(v);
    else if (a == "--tolerance") o.tolerance = std::atof(v);
    else if (a == "--csv") o.csv = v;
    else if (a == "--json") o.json = v;
    else return std::fprintf(stderr, "unknown option %s (see --help)\n", a.c_str()), false;
  }
  if (o.dimension != 2 && o.dimension != 3)
    return std::fprintf(stderr, "--dimension must be 2 or 3\n"), false;
  if (!(o.lo > 0.0 && o.hi < 1.0 && o.lo <= o.hi && o.step > 0.0))
    return std::fprintf(stderr, "need 0 < min <= max < 1 and step > 0\n"), false;
  if (!(o.ra > 0.0)) return std::fprintf(stderr, "--ra must be > 0\n"), false;
  return true;
}

struct Row {
  double eps, alpha, ea, eb, ea_error, eb_error;
  InstabilityConditions c100, c085;
  SplitStressDefect defect;
};

}    // namespace

int main(int argc, char **argv)
{
  Options o;
  if (!parse(argc, argv, o)) return argc > 1 && (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) ? 0 : 2;

  std::vector<double> values;
  for (double v = o.lo; v <= o.hi + 1e-9; v += o.step) values.push_back(std::round(v * 1e6) / 1e6);

  std::vector<Row> rows;
  for (double eps : values)
    for (double alpha : values) {
      const auto a = kernel_gradient_error(o.dimension, eps, alpha, o.ra, NeighbourSmoothing::UNREFINED, o.tolerance);
      const auto b = kernel_gradient_error(o.dimension, eps, alpha, o.ra, NeighbourSmoothing::REFINED, o.tolerance);
      rows.push_back({eps, alpha, a.value, b.value, a.error_estimate, b.error_estimate,
                      instability_conditions(eps, alpha, o.ra, 1.0),
                      instability_conditions(eps, alpha, o.ra, 0.85),
                      split_stress_defect(o.dimension, eps, alpha, o.ra)});
    }

  FILE *out = std::fopen(o.csv.c_str(), "w");
  if (!out) return std::fprintf(stderr, "cannot write %s\n", o.csv.c_str()), 1;
  std::fprintf(out, "eps_r,alpha_r,E_a,E_b,E_a_error,E_b_error,cond1,cond2_d1.00,cond3_d1.00,"
                    "cond2_d0.85,cond3_d0.85,stable_d1.00,stable_d0.85,defect_neighbours,defect_daughters\n");
  double max_relative_error = 0.0;
  for (const auto &r : rows) {
    std::fprintf(out, "%.4f,%.4f,%.8e,%.8e,%.2e,%.2e,%d,%d,%d,%d,%d,%d,%d,%.6e,%.6e\n", r.eps, r.alpha, r.ea,
                 r.eb, r.ea_error, r.eb_error, r.c100.daughters_too_close, r.c100.refined_neighbours,
                 r.c100.unrefined_neighbour, r.c085.refined_neighbours, r.c085.unrefined_neighbour,
                 !r.c100.any(), !r.c085.any(), r.defect.neighbours, r.defect.daughters);
    if (r.ea > 0) max_relative_error = std::max(max_relative_error, r.ea_error / r.ea);
    if (r.eb > 0) max_relative_error = std::max(max_relative_error, r.eb_error / r.eb);
  }
  std::fclose(out);

  auto best = [&](auto accept, auto score) {
    const Row *b = nullptr;
    for (const auto &r : rows)
      if (accept(r) && (!b || score(r) < score(*b))) b = &r;
    return b;
  };
  auto worst = [](const Row &r) { return std::max(r.ea, r.eb); };
  const Row *min_a = best([](const Row &) { return true; }, [](const Row &r) { return r.ea; });
  const Row *min_b = best([](const Row &) { return true; }, [](const Row &r) { return r.eb; });
  const Row *best100 = best([](const Row &r) { return !r.c100.any(); }, worst);
  const Row *best085 = best([](const Row &r) { return !r.c085.any(); }, worst);

  std::string json = "{\n";
  char line[512];
  std::snprintf(line, sizeof line, "  \"dimension\": %d,\n  \"r_a\": %g,\n  \"grid\": [%g, %g, %g],\n"
                "  \"max_relative_quadrature_error\": %.2e,\n", o.dimension, o.ra, o.lo, o.hi, o.step,
                max_relative_error);
  json += line;
  auto entry = [&](const char *name, const Row *r, bool comma) {
    if (!r) return json += std::string("  \"") + name + "\": null" + (comma ? ",\n" : "\n"), void();
    std::snprintf(line, sizeof line, "  \"%s\": {\"eps_r\": %.3f, \"alpha_r\": %.3f, \"E_a\": %.5g, \"E_b\": %.5g}%s\n",
                  name, r->eps, r->alpha, r->ea, r->eb, comma ? "," : "");
    json += line;
  };
  entry("minimum_E_a", min_a, true);
  entry("minimum_E_b", min_b, true);
  entry("best_stable_d1.00", best100, true);
  entry("best_stable_d0.85", best085, true);
  json += "  \"paper_points\": [\n";
  const double paper[4][2] = {{0.5, 0.5}, {0.55, 0.5}, {0.55, 0.6}, {0.55, 0.7}};
  for (int k = 0; k < 4; k++) {
    const double eps = paper[k][0], alpha = paper[k][1];
    const auto a = kernel_gradient_error(o.dimension, eps, alpha, o.ra, NeighbourSmoothing::UNREFINED, o.tolerance);
    const auto b = kernel_gradient_error(o.dimension, eps, alpha, o.ra, NeighbourSmoothing::REFINED, o.tolerance);
    const auto defect = split_stress_defect(o.dimension, eps, alpha, o.ra);
    std::snprintf(line, sizeof line, "    {\"eps_r\": %.2f, \"alpha_r\": %.2f, \"E_a\": %.5g, \"E_b\": %.5g, "
                  "\"stable_d1.00\": %s, \"stable_d0.85\": %s, \"defect_neighbours\": %.4g, "
                  "\"defect_daughters\": %.4g}%s\n", eps, alpha, a.value, b.value,
                  stable_refinement(eps, alpha, o.ra, 1.0) ? "true" : "false",
                  stable_refinement(eps, alpha, o.ra, 0.85) ? "true" : "false", defect.neighbours,
                  defect.daughters, k < 3 ? "," : "");
    json += line;
  }
  json += "  ],\n";
  // the push at the edge of a refined zone (level_edge_defect), separation 0.5
  json += "  \"level_edge_separation_0.5\": [\n";
  const double ratios[3] = {0.5, 0.7, 0.9};
  for (int k = 0; k < 3; k++) {
    const auto edge = level_edge_defect(o.dimension, 0.5, ratios[k], o.ra);
    std::snprintf(line, sizeof line, "    {\"alpha_r\": %.1f, \"coarse\": %.4g, \"daughters\": %.4g}%s\n",
                  ratios[k], edge.neighbours, edge.daughters, k < 2 ? "," : "");
    json += line;
  }
  json += "  ]\n}\n";
  std::fputs(json.c_str(), stdout);
  if (!o.json.empty()) {
    FILE *j = std::fopen(o.json.c_str(), "w");
    if (j) {
      std::fputs(json.c_str(), j);
      std::fclose(j);
    }
  }
  return 0;
}
