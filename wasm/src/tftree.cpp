// TfTree: rtl::TfTree<std::string, RigidTfND<D, double>> behind an integer handle (the JS class owns it).
#include "adapter.h"
#include "schema.h"

#include <Eigen/Core>

#include <rtl/core/Quaternion.h>
#include <rtl/tf/RigidTfND.h>
#include <rtl/tf/TfTree.h>

namespace rtl_wasm {
namespace {

struct TreeBase {
  virtual ~TreeBase() = default;
  virtual int dim() const = 0;
  virtual bool insert(const std::string& name, const std::string& parent, const double* q, const double* t) = 0;
  virtual bool erase(const std::string& name) = 0;
  virtual bool contains(const std::string& name) const = 0;
  virtual std::size_t size() const = 0;
  virtual val tf(const std::string& from, const std::string& to) const = 0;
  virtual val apply(const std::string& from, const std::string& to, const double* xyz, std::size_t len) const = 0;
};

template <int D>
struct Tree final : TreeBase {
  using Tf = rtl::RigidTfND<D, double>;
  using V = rtl::VectorND<D, double>;
  rtl::TfTree<std::string, Tf> tree;
  explicit Tree(const std::string& root) : tree(root) {}
  int dim() const override { return D; }

  // q: 2D {angle}; 3D unit quaternion {w, x, y, z} (normalised by the JS layer).
  static Tf make(const double* q, const double* t) {
    if constexpr (D == 2) {
      return Tf(q[0], t[0], t[1]);
    } else {
      return Tf(rtl::Quaternion<double>(q[0], q[1], q[2], q[3]), V(t[0], t[1], t[2]));
    }
  }
  bool insert(const std::string& name, const std::string& parent, const double* q, const double* t) override {
    return tree.insert(name, make(q, t), parent);
  }
  bool erase(const std::string& name) override { return tree.erase(name); }
  bool contains(const std::string& name) const override { return tree.contains(name); }
  std::size_t size() const override { return tree.size(); }

  Tf squashed(const std::string& from, const std::string& to) const {
    for (const std::string* k : {&from, &to})
      if (!tree.contains(*k)) throw std::out_of_range("unknown frame '" + *k + "'");
    return tree.tf(from, to).squash();
  }
  val tf(const std::string& from, const std::string& to) const override {
    const Tf s = squashed(from, to);
    Eigen::Matrix<double, D, D, Eigen::RowMajor> R = s.rotMat().data();
    Eigen::Matrix<double, D + 1, D + 1, Eigen::RowMajor> H = Eigen::Matrix<double, D + 1, D + 1, Eigen::RowMajor>::Identity();
    H.template topLeftCorner<D, D>() = R;
    H.template topRightCorner<D, 1>() = s.trVec().data();
    val r = val::object();
    r.set("dim", D);
    r.set("rotation", f64(R.data(), D * D));
    r.set("translation", f64(s.trVec().data().data(), D));
    r.set("matrix", f64(H.data(), (D + 1) * (D + 1)));
    return r;
  }
  val apply(const std::string& from, const std::string& to, const double* xyz, std::size_t len) const override {
    const Tf s = squashed(from, to);
    const auto n = static_cast<Eigen::Index>(len / D);
    std::vector<double> out(len);
    Eigen::Map<Eigen::Matrix<double, D, Eigen::Dynamic>>(out.data(), D, n) =
        (s.rotMat().data() * Eigen::Map<const Eigen::Matrix<double, D, Eigen::Dynamic>>(xyz, D, n)).colwise() +
        s.trVec().data();
    return f64(out);
  }
};

TreeBase* handle(std::uintptr_t h) { return reinterpret_cast<TreeBase*>(h); }

// new TfTree()'s options and TfTree.insert()'s transformation (wasm/js/tftree.js writes them by these names after
// checking them; schema.h). The results are a handle, a flag or objects built here (NamedObjectResult).
struct TreeOptions {
  int dim = 0;
  template <class F>
  void fields(F& f) {
    f("dim", dim);
  }
};
struct RigidOptions {
  double rotation[4] = {};     // 2D: {angle, 0, 0, 0}; 3D: a unit quaternion {w, x, y, z}
  double translation[3] = {};  // 2D: {x, y, 0}
  template <class F>
  void fields(F& f) {
    f("rotation", rotation);
    f("translation", translation);
  }
};

val tfCreate(const std::string& root, std::uintptr_t options) {
  return guarded([&] {
    const int dim = readOptions<TreeOptions>(options).dim;
    TreeBase* t = dim == 3 ? static_cast<TreeBase*>(new Tree<3>(root)) : static_cast<TreeBase*>(new Tree<2>(root));
    return val(static_cast<double>(reinterpret_cast<std::uintptr_t>(t)));
  });
}
val tfInsert(std::uintptr_t h, const std::string& name, const std::string& parent, std::uintptr_t options) {
  return guarded([&] {
    const auto tf = readOptions<RigidOptions>(options);
    return val(handle(h)->insert(name, parent, tf.rotation, tf.translation));
  });
}
bool tfErase(std::uintptr_t h, const std::string& name) { return handle(h)->erase(name); }
bool tfContains(std::uintptr_t h, const std::string& name) { return handle(h)->contains(name); }
double tfSize(std::uintptr_t h) { return static_cast<double>(handle(h)->size()); }
val tfGet(std::uintptr_t h, const std::string& from, const std::string& to) {
  return guarded([&] { return handle(h)->tf(from, to); });
}
val tfApply(std::uintptr_t h, const std::string& from, const std::string& to, std::uintptr_t ptr, std::size_t len) {
  return guarded([&] {
    const double* xyz = doubles(ptr);
    checkPoints("TfTree.transformPoints", xyz, len, static_cast<std::size_t>(handle(h)->dim()), 0, true);
    return handle(h)->apply(from, to, xyz, len);
  });
}
void tfDestroy(std::uintptr_t h) { delete handle(h); }

}  // namespace
}  // namespace rtl_wasm

EMSCRIPTEN_BINDINGS(rtl_tftree) {
  using namespace rtl_wasm;
  emscripten::function("tfCreate", &tfCreate);
  registerCall<TreeOptions, NamedObjectResult>("tfCreate");
  emscripten::function("tfInsert", &tfInsert);
  registerCall<RigidOptions, NamedObjectResult>("tfInsert");
  emscripten::function("tfErase", &tfErase);
  emscripten::function("tfContains", &tfContains);
  emscripten::function("tfSize", &tfSize);
  emscripten::function("tfGet", &tfGet);
  emscripten::function("tfApply", &tfApply);
  emscripten::function("tfDestroy", &tfDestroy);
}
