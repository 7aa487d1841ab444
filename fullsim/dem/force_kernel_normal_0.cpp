// The force kernels of the laws whose normal part is NormalParts' part 0 (force_kernel.hpp).
#include "fullsim/dem/law_forces.hpp"

namespace feedflow {

template std::unique_ptr<ForceKernel> make_force_kernel_of_normal<0>(const ContactLawChoice&,
                                                                     const DemParameters&);

}  // namespace feedflow
