// _core.CdemSimulation: Paper B's two-scale contact model on CST-meshed
// blocks (dda::cdem::Model behind dda::cdem::ModelStepper) stepped from
// Python, its state as numpy arrays (copies). dda.CdemSimulation
// (dda/_simulation.py) derives from it; dda.Simulation makes one for a
// scene whose "model" is "cdem". Stepping, the GIL and other threads:
// stepping.hpp.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <cmath>
#include <functional>
#include <limits>
#include <type_traits>
#include <memory>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "dda/cdem/stepper.hpp"
#include "dda/io/run.hpp"
#include "dda/io/scene_file.hpp"
#include "stepping.hpp"

namespace dda::py_bindings {

namespace {

using cdem::Model;

class PyCdem final : public PyStepped {
 public:
  PyCdem(std::shared_ptr<io::SceneFile> file, int threads, const std::string& label) : PyStepped(std::move(file)) {
    if (file_->model != io::ContactModel::kCdem)
      throw py::value_error(label + ": model: \"" + std::string(io::model_name(file_->model)) +
                            "\": Paper A's model runs in dda.Simulation");
    if (threads != 1) throw py::value_error("threads: the cdem model steps on one thread");
    try {
      py::gil_scoped_release release;  // meshing and the critical step's power iteration
      auto s = std::make_unique<cdem::ModelStepper>(Model(io::cdem_scene(*file_)));
      model_ = &s->model();
      stepper_ = std::move(s);
    } catch (const SceneError& e) {
      // The model's own checks (dt above the mesh's critical step, ...): as the file's.
      throw io::SceneFileError(label + ": " + e.what());
    }
    io::check_step_count(*file_, model_->dt(), label);
  }

  const Model& read() const {
    check_idle();
    return *model_;
  }

 private:
  // The full state (Model::save_state): nodes, mesh, clones, sub-models,
  // the energy ledger, the contact log, the clock.
  void save(ByteWriter& out) const override { model_->save_state(out); }
  void restore(ByteReader& in) override { model_->restore_state(in); }

  Model* model_ = nullptr;  // stepper_'s model
};

py::array_t<double> points_array(std::size_t n, const std::function<Vec2(std::size_t)>& at) {
  py::array_t<double> a = new_array(static_cast<py::ssize_t>(n), 2);
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = at(i);
    w(static_cast<py::ssize_t>(i), 0) = p.x, w(static_cast<py::ssize_t>(i), 1) = p.y;
  }
  return a;
}

template <class T>
py::array_t<T> column(std::size_t n, const std::function<T(std::size_t)>& at) {
  py::array_t<T> a(static_cast<py::ssize_t>(n));
  auto w = a.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < n; ++i) w(static_cast<py::ssize_t>(i)) = at(i);
  return a;
}

// A record list as a dict of columns: name -> (k,) or (k, 2) array.
template <class R>
class Columns {
 public:
  explicit Columns(const std::vector<R>& rows) : rows_(rows) {}
  template <class T>
  Columns& add(const char* name, T R::*field) {
    if constexpr (std::is_same_v<T, Vec2>)
      d_[name] = points_array(rows_.size(), [&](std::size_t i) { return rows_[i].*field; });
    else
      d_[name] = column<T>(rows_.size(), [&](std::size_t i) { return rows_[i].*field; });
    return *this;
  }
  py::dict dict() const { return d_; }

 private:
  const std::vector<R>& rows_;
  py::dict d_;
};

const char* kind_name(cdem::NodeKind k) {
  switch (k) {
    case cdem::NodeKind::kCoarse: return "coarse";
    case cdem::NodeKind::kFine: return "fine";
    case cdem::NodeKind::kHanging: return "hanging";
    case cdem::NodeKind::kDead: return "dead";
  }
  return "coarse";
}

const char* criterion_name(cdem::SeparationCriterion c) {
  switch (c) {
    case cdem::SeparationCriterion::kTension: return "tension";
    case cdem::SeparationCriterion::kShear: return "shear";
    case cdem::SeparationCriterion::kSlidOff: return "slid_off";
  }
  return "tension";
}

py::dict separation_columns(const std::vector<cdem::SeparationRecord>& rows) {
  using S = cdem::SeparationRecord;
  py::dict d = Columns<S>(rows)
                   .add("time", &S::time)
                   .add("main_node", &S::main_node)
                   .add("main_block", &S::main_block)
                   .add("target_block", &S::target_block)
                   .add("normal_force", &S::normal_force)
                   .add("shear_force", &S::shear_force)
                   .add("limit", &S::limit)
                   .add("contact_area", &S::contact_area)
                   .add("fine", &S::fine)
                   .dict();
  py::list crit;
  for (const S& r : rows) crit.append(criterion_name(r.criterion));
  d["criterion"] = crit;
  return d;
}

// A property getter: of(model, b) for each block b, as (n, 2) points or (n,)
// values (a copy).
template <class T>
auto per_block(T (Model::*of)(int) const) {
  return [of](const PyCdem& s) {
    const Model& md = s.read();
    const auto n = static_cast<std::size_t>(md.block_count());
    const auto at = [&](std::size_t b) { return (md.*of)(static_cast<int>(b)); };
    if constexpr (std::is_same_v<T, Vec2>)
      return points_array(n, at);
    else
      return column<T>(n, at);
  };
}

// The active elements (of one block, or all with block < 0).
std::vector<const cdem::Element*> active_elements(const Model& m, int block) {
  if (block >= m.block_count()) throw py::index_error("block index out of range");
  std::vector<const cdem::Element*> out;
  for (const cdem::Element& e : m.state().mesh.elems)
    if (e.active && (block < 0 || e.block == block)) out.push_back(&e);
  return out;
}

}  // namespace

void bind_cdem(py::module_& m) {
  py::class_<PyCdem> c(m, "CdemSimulation");
  c.def(py::init<std::shared_ptr<io::SceneFile>, int, const std::string&>(), py::arg("scene_file"),
        py::arg("threads") = 1, py::arg("label") = "<scene>")
      // --- stepping (and step(n): bind_stepping) ---
      .def(
          "_run",
          [](py::object self, double until, std::int64_t every, py::object callback) {
            PyCdem& s = self.cast<PyCdem&>();
            if (every < 1) throw py::value_error("every: must be >= 1");
            if (!std::isfinite(until)) throw py::value_error("until: must be a finite time, s");
            s.check_idle();
            return s.run_steps(self, std::numeric_limits<std::int64_t>::max(), until, every, callback);
          },
          py::arg("until"), py::arg("every"), py::arg("callback"))
      .def_property_readonly("time", [](const PyCdem& s) { return s.read().time(); }, "Simulated time, s.")
      .def_property_readonly("step_count", [](const PyCdem& s) { return s.read().step_count(); })
      .def_property_readonly("dt", [](const PyCdem& s) { return s.read().dt(); }, "The step, s.")
      .def_property_readonly("threads", [](const PyCdem&) { return 1; }, "The cdem model steps on one thread.")
      .def_property_readonly("critical_dt", [](const PyCdem& s) { return s.read().critical_dt(); },
                             "Critical step of the coarse mesh, 2 / omega_max of M^-1 K, s.")
      .def_property_readonly("element_critical_dt", [](const PyCdem& s) { return s.read().element_critical_dt(); },
                             "The element bound min_e 2 / omega_max(e), s.")
      // --- blocks ---
      .def_property_readonly("block_count", [](const PyCdem& s) { return s.read().block_count(); })
      .def_property_readonly("positions", per_block(&Model::block_mean_position),
                             "(n, 2) each block's mass-weighted mean node position, m (copy).")
      .def_property_readonly("velocities", per_block(&Model::block_velocity),
                             "(n, 2) each block's momentum / mass, m/s (copy).")
      .def_property_readonly("displacements", per_block(&Model::block_displacement),
                             "(n, 2) each block's mean position minus its initial value, m (copy).")
      .def_property_readonly("masses", per_block(&Model::block_mass),
                             "(n,) block masses, kg/m (copy).")
      // --- nodes and elements ---
      .def_property_readonly("node_count", [](const PyCdem& s) { return s.read().node_count(); })
      .def_property_readonly(
          "node_positions",
          [](const PyCdem& s) {
            const auto& x = s.read().state().nodes.x;
            return points_array(x.size(), [&](std::size_t i) { return x[i]; });
          },
          "(N, 2) node positions, m (copy; every node ever made, see node_kinds).")
      .def_property_readonly(
          "node_velocities",
          [](const PyCdem& s) {
            const auto& v = s.read().state().nodes.v;
            return points_array(v.size(), [&](std::size_t i) { return v[i]; });
          },
          "(N, 2) node velocities, m/s (copy).")
      .def_property_readonly(
          "node_masses",
          [](const PyCdem& s) {
            const auto& mass = s.read().state().nodes.m;
            return column<double>(mass.size(), [&](std::size_t i) { return mass[i]; });
          },
          "(N,) lumped node masses, kg/m (copy).")
      .def_property_readonly(
          "node_blocks",
          [](const PyCdem& s) {
            const auto& b = s.read().state().nodes.block;
            return column<int>(b.size(), [&](std::size_t i) { return b[i]; });
          },
          "(N,) each node's block (copy).")
      .def_property_readonly(
          "node_kinds",
          [](const PyCdem& s) {
            const auto& k = s.read().state().nodes.kind;
            py::list out;
            for (cdem::NodeKind x : k) out.append(kind_name(x));
            return py::module_::import("numpy").attr("array")(out, "U7");
          },
          "(N,) \"coarse\", \"fine\" (in-place patch), \"hanging\" or \"dead\" (copy).")
      .def(
          "elements",
          [](const PyCdem& s, int block) {
            const std::vector<const cdem::Element*> es = active_elements(s.read(), block);
            py::array_t<int> a(std::vector<py::ssize_t>{static_cast<py::ssize_t>(es.size()), 3});
            auto w = a.mutable_unchecked<2>();
            for (std::size_t i = 0; i < es.size(); ++i)
              for (int k = 0; k < 3; ++k) w(static_cast<py::ssize_t>(i), k) = es[i]->n[static_cast<std::size_t>(k)];
            return a;
          },
          py::arg("block") = -1,
          "(m, 3) the active constant-strain triangles' node indices, counter-clockwise, of one block\n"
          "(or of all with block=-1; element_blocks() says whose) (copy).")
      .def(
          "element_blocks",
          [](const PyCdem& s) {
            const std::vector<const cdem::Element*> es = active_elements(s.read(), -1);
            return column<int>(es.size(), [&](std::size_t i) { return es[i]->block; });
          },
          "(m,) the block of each of elements() (copy).")
      .def(
          "element_stresses",
          [](const PyCdem& s, int block) {
            const std::vector<const cdem::Element*> es = active_elements(s.read(), block);
            py::array_t<double> a = new_array(static_cast<py::ssize_t>(es.size()), 3);
            auto w = a.mutable_unchecked<2>();
            for (std::size_t i = 0; i < es.size(); ++i)
              for (int k = 0; k < 3; ++k) w(static_cast<py::ssize_t>(i), k) = es[i]->stress[k];
            return a;
          },
          py::arg("block") = -1, "(m, 3) (sxx, syy, sxy) of each of elements(block), Pa (copy).")
      // --- contact ---
      .def_property_readonly("contact_count", [](const PyCdem& s) { return s.stepper().contact_count(); },
                             "Clone nodes now (node-to-edge penalty baseline: its springs).")
      .def(
          "clones",
          [](const PyCdem& s) {
            const std::vector<cdem::CloneView> cl = s.read().clones();
            using C = cdem::CloneView;
            py::dict d = Columns<C>(cl)
                             .add("main_node", &C::main_node)
                             .add("point", &C::point)
                             .add("force", &C::force)
                             .add("normal", &C::normal)
                             .add("fine", &C::fine)
                             .dict();
            py::array_t<int> target(std::vector<py::ssize_t>{static_cast<py::ssize_t>(cl.size()), 2});
            auto t = target.mutable_unchecked<2>();
            for (std::size_t i = 0; i < cl.size(); ++i)
              t(static_cast<py::ssize_t>(i), 0) = cl[i].target[0], t(static_cast<py::ssize_t>(i), 1) = cl[i].target[1];
            d["target"] = target;
            d["weight"] = points_array(cl.size(), [&](std::size_t i) { return Vec2{cl[i].weight[0], cl[i].weight[1]}; });
            return d;
          },
          "The clone nodes now (Sect. 4), a dict of columns (copies): main_node (k,), target (k, 2)\n"
          "nodes with weight (k, 2) (the tied point is sum weight * node; target -1: none),\n"
          "point (k, 2), force (k, 2) on the main node, N/m (Eq. 11), normal (k, 2), fine (k,).")
      .def(
          "touches",
          [](const PyCdem& s) {
            using T = cdem::TouchRecord;
            return Columns<T>(s.read().touches())
                .add("time", &T::time)
                .add("step_start", &T::step_start)
                .add("dt1", &T::dt1)
                .add("dt2", &T::dt2)
                .add("fine", &T::fine)
                .add("main_node", &T::main_node)
                .add("main_block", &T::main_block)
                .add("target_block", &T::target_block)
                .add("node_to_node", &T::node_to_node)
                .add("point", &T::point)
                .add("mass_main", &T::mass_main)
                .add("mass_target", &T::mass_target)
                .add("v_main", &T::v_main)
                .add("v_target", &T::v_target)
                .add("v_clone", &T::v_clone)
                .add("energy_loss", &T::energy_loss)
                .add("energy_loss_eq5", &T::energy_loss_eq5)
                .add("energy_loss_eq5_group", &T::energy_loss_eq5_group)
                .add("impulse_normal", &T::impulse_normal)
                .add("impulse_tangential", &T::impulse_tangential)
                .add("coulomb_capped", &T::coulomb_capped)
                .add("subdivision", &T::subdivision)
                .add("radius", &T::radius)
                .dict();
          },
          "Every touch so far (Sects. 3-4), a dict of columns (copies): time, step_start, dt1, dt2\n"
          "(the free-motion and contact parts of the step), main_node, main_block, target_block,\n"
          "node_to_node, point (k, 2), mass_main, mass_target, v_main, v_target, v_clone (k, 2; Eq. 4),\n"
          "energy_loss (measured), energy_loss_eq5, energy_loss_eq5_group (Eq. 5), impulse_normal,\n"
          "impulse_tangential, coulomb_capped, subdivision (k of Sect. 5), radius (c dt2), fine.")
      .def(
          "separations", [](const PyCdem& s) { return separation_columns(s.read().separations()); },
          "Every clone removed so far, a dict of columns (copies): time, main_node, main_block,\n"
          "target_block, criterion (\"tension\" Eq. 6, \"slid_off\"), normal_force, shear_force, limit,\n"
          "contact_area, fine.")
      .def(
          "slips", [](const PyCdem& s) { return separation_columns(s.read().slips()); },
          "Every clone that started sliding (Eqs. 7-10), the columns of separations().")
      .def(
          "submodels",
          [](const PyCdem& s) {
            using R = cdem::SubModelRecord;
            return Columns<R>(s.read().submodels())
                .add("created", &R::created)
                .add("deleted", &R::deleted)
                .add("main_node", &R::main_node)
                .add("main_block", &R::main_block)
                .add("target_block", &R::target_block)
                .add("elements", &R::elements)
                .add("k", &R::k)
                .add("sub_nodes", &R::sub_nodes)
                .add("substeps", &R::substeps)
                .add("substeps_taken", &R::substeps_taken)
                .add("radius", &R::radius)
                .add("kinetic_dropped", &R::kinetic_dropped)
                .add("strain_change", &R::strain_change)
                .dict();
          },
          "Every sub-model of the local subdivision so far (Sect. 5), a dict of columns (copies):\n"
          "created, deleted (-1 while it lives), main_node, main_block, target_block, elements\n"
          "(parents), k, sub_nodes, substeps, substeps_taken, radius, kinetic_dropped, strain_change.")
      .def_property_readonly("live_submodels", [](const PyCdem& s) { return s.read().live_submodels(); })
      // --- energy and momentum ---
      .def("energy", [](const PyCdem& s) { return s.stepper().energy(); },
           "The energy budget in dda.Energy's terms, J/m: kinetic, gravity, strain, contact (the\n"
           "node-to-edge baseline's springs); dissipated = touch, refinement and deletion losses;\n"
           "balance_error = minus the energy account's `other`.")
      .def(
          "energy_account",
          [](const PyCdem& s) {
            const cdem::CdemEnergyAccount a = s.read().energy_account();
            return py::dict(py::arg("time") = a.time, py::arg("initial") = a.initial, py::arg("kinetic") = a.kinetic,
                            py::arg("strain") = a.strain, py::arg("gravity") = a.gravity,
                            py::arg("touch_loss") = a.touch_loss, py::arg("touch_loss_eq5") = a.touch_loss_eq5,
                            py::arg("touch_loss_eq5_group") = a.touch_loss_eq5_group,
                            py::arg("refine_loss") = a.refine_loss, py::arg("deletion_loss") = a.deletion_loss,
                            py::arg("other") = a.other, py::arg("submodel_kinetic") = a.submodel_kinetic);
          },
          "Where the energy went, J/m: initial = kinetic + strain + gravity + touch_loss +\n"
          "refine_loss + deletion_loss + other (touch_loss measured; touch_loss_eq5 by Eq. 5).")
      .def_property_readonly(
          "momentum",
          [](const PyCdem& s) {
            const Vec2 p = s.read().momentum();
            py::array_t<double> a(2);
            a.mutable_at(0) = p.x, a.mutable_at(1) = p.y;
            return a;
          },
          "(2,) momentum of the moving blocks, kg m/s per m.");
  bind_stepping(c);
}

}  // namespace dda::py_bindings
