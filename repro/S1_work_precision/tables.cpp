// S1 work precision: the columns of runs.csv and orders.csv
// (work_precision.hpp).
#include <cmath>
#include <string>
#include <vector>

#include "repro/S1_work_precision/work_precision.hpp"

namespace s1 {
namespace {
repro::Column<RunRow> ran(const char* name, double (*value)(const RunRow&)) {
  return {name, [value](const RunRow& w) { return repro::cell_if(w.r.ok, value(w)); }};
}
}  // namespace

const std::vector<repro::Column<RunRow>> kRunColumns = {
    {"scene", [](const RunRow& w) { return w.c.scene; }},
    {"option", [](const RunRow& w) { return w.c.option; }},
    {"measure", [](const RunRow& w) { return w.measure; }},
    {"dt", [](const RunRow& w) { return w.dt; }},
    {"dt_over_crit_start", [](const RunRow& w) { return w.r.ratio0; }},
    ran("dt_over_crit_max", [](const RunRow& w) { return w.r.ratio_max; }),
    ran("wall_s", [](const RunRow& w) { return w.t.wall; }),
    ran("cpu_s", [](const RunRow& w) { return w.t.cpu; }),
    ran("error", [](const RunRow& w) { return w.error; }),
    {"local_order", [](const RunRow& w) { return repro::cell_if(std::isfinite(w.local), w.local); }},
    {"status", [](const RunRow& w) { return w.r.ok ? "ok" : "stopped: " + w.r.message; }}};

namespace {
// orders.csv: one row per curve.
using Curve = CurveSummary;
repro::Column<Curve> fitted(const char* name, const repro::stab::Order Curve::*order, double repro::stab::Order::*v) {
  return {name, [order, v](const Curve& cs) { return repro::cell_if((cs.*order).valid(), (cs.*order).*v); }};
}
repro::Column<Curve> at_paper(const char* name, double Curve::*field) {
  return {name, [field](const Curve& cs) { return repro::cell_if(cs.*field >= 0.0, cs.*field); }};
}
}  // namespace

const std::vector<repro::Column<Curve>> kOrderColumns = {
    repro::field("scene", &Curve::scene),
    repro::field("option", &Curve::option),
    repro::field("measure", &Curve::measure),
    repro::field("reference", &Curve::reference),
    fitted("order", &Curve::order, &repro::stab::Order::p),
    {"fit_points", [](const Curve& cs) { return cs.order.used; }},
    fitted("fit_dt_lo", &Curve::order, &repro::stab::Order::dt_lo),
    fitted("fit_dt_hi", &Curve::order, &repro::stab::Order::dt_hi),
    fitted("order_all_stable", &Curve::order_all, &repro::stab::Order::p),
    at_paper("error_at_paper_dt", &Curve::error_at_paper),
    at_paper("wall_at_paper_dt", &Curve::wall_at_paper),
    at_paper("cpu_at_paper_dt", &Curve::cpu_at_paper),
    repro::field("paper_dt_over_crit", &Curve::ratio_at_paper),
    repro::field("largest_stable_dt_over_crit", &Curve::largest_stable_ratio),
    {"note", [](const Curve& cs) { return cs.order.note; }}};

}  // namespace s1
