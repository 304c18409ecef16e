// Models shared by the wec tests, built from the scene's own parameter defaults (one source of truth).
#pragma once

#include "wec/wec_model.hpp"
#include "wec/wec_parameters.hpp"

namespace wec_test {

// The default single float (L = 10 m, θ0 = −30°, a = 3 m, B_PTO = 3.52e6 N·m·s) with radiation kernels of
// 40 s sampled at `dt`.
inline maris::wec::WecModel model(const maris::wec::WecParameters& p, double dt = 0.05) {
  maris::wec::WecModel m = maris::wec::buildWecModel(p);
  maris::wec::buildRadiation(m, p.kernel_duration, dt);
  return m;
}
inline maris::wec::WecParameters defaults() { return maris::wec::WecParameters{}; }
// The default float's model, built once per test program (kernels and fits cost ~0.1 s).
inline const maris::wec::WecModel& defaultModel() {
  static const maris::wec::WecModel m = model(defaults());
  return m;
}

}  // namespace wec_test
