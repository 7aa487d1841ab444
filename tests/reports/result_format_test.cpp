// Result labels: the one reduced-model key of every simulated scene reads as such in reports.
#include <gtest/gtest.h>

#include "reports/result_format.hpp"

namespace feedflow {
namespace {

// The reduced-model key is the quantity's key with one suffix, whatever the scene.
TEST(ResultFormat, ReducedModelKeyHasOneNaming) {
  EXPECT_EQ(reduced_model_key("mass_flow_rate"), "mass_flow_rate_reduced_model");
  EXPECT_EQ(reduced_model_key("dynamic_angle_of_repose"), "dynamic_angle_of_repose_reduced_model");
}

// Reports label the reduced-model value as the quantity plus "(reduced model)", and leave
// other names (including a bare "reduced_model") as words.
TEST(ResultFormat, ReducedModelLabelNamesTheQuantity) {
  EXPECT_EQ(quantity_label(reduced_model_key("mass_flow_rate")), "mass flow rate (reduced model)");
  EXPECT_EQ(quantity_label("critical_outlet_width"), "critical outlet width");
  EXPECT_EQ(quantity_label("hopper.semi_angle"), "semi angle");
  EXPECT_EQ(quantity_label("_reduced_model"), " reduced model");
}

}  // namespace
}  // namespace feedflow
