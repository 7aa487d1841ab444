#pragma once
// The vector widths a batch of contacts runs its lanes with: `evaluate` (two lanes, any x86-64),
// `evaluate_avx2` (four) and `evaluate_avx512` (eight) compile the batch's one loop
// (`Batch::lanes`) for each instruction set, and `evaluate_with` picks one at run time from the
// widest the processor has (lane_bits_available, force_kernel.hpp). All give the same bits:
// each lane's arithmetic is the scalar one, and the translation unit is built without
// floating-point contraction (fullsim/CMakeLists.txt).
namespace feedflow {

template <class Batch>
struct LaneWidths {
  template <class Law>
  [[gnu::noinline, gnu::flatten]] void evaluate(const Law& law, double dt) {
    static_cast<Batch*>(this)->lanes(law, dt);
  }
#if defined(__x86_64__)
  template <class Law>
  [[gnu::noinline, gnu::flatten, gnu::target("avx2,fma")]] void evaluate_avx2(const Law& law,
                                                                             double dt) {
    static_cast<Batch*>(this)->lanes(law, dt);
  }
  template <class Law>
  [[gnu::noinline, gnu::flatten, gnu::target("avx512f,avx512vl,avx512dq,avx2,fma")]] void
  evaluate_avx512(const Law& law, double dt) {
    static_cast<Batch*>(this)->lanes(law, dt);
  }
#endif
  // The variant for `lane_bits` (512, 256 or 128, already capped by lane_bits_available()).
  template <class Law>
  void evaluate_with(int lane_bits, const Law& law, double dt) {
#if defined(__x86_64__)
    if (lane_bits >= 512) evaluate_avx512(law, dt);
    else if (lane_bits >= 256) evaluate_avx2(law, dt);
    else evaluate(law, dt);
#else
    (void)lane_bits;
    evaluate(law, dt);
#endif
  }
};

}  // namespace feedflow
