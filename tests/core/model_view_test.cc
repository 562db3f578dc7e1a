// The typed view of model.json (core/model_view.h): each key's absence means what readers took it
// to mean (no forces, no delay, no inputs, the vessel's own length), a malformed model is an
// InputError naming the key, and the edits set only the keys the post-fit steps own.
#include "core/model_view.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace usvid {
namespace {

const nlohmann::json kEquationModel = {
    {"method", "gp"},
    {"vessel", "odin-hs"},
    {"states", {"u", "v", "r"}},
    {"inputs", {"tau_x", "tau_n"}},
    {"equations", {{"u", "-0.1*u+tau_x"}, {"r", "0.02-0.5*r+tau_n"}}},
    {"parameters", {{"r.bias", 0.02}}},
    {"preprocessing", {{"forces", "waterjet"}, {"delay_s", 0.2}}},
    {"calibration", {{"yaw_bias", "zigzag"}}},
    {"train", {{"seconds", 1.5}}}};

TEST(ModelViewTest, ReadsAnEquationModel) {
  const ModelView m(kEquationModel);
  EXPECT_EQ(m.Method(), "gp");
  EXPECT_EQ(m.Vessel(), "odin-hs");
  EXPECT_TRUE(m.HasEquations());
  EXPECT_FALSE(m.IsVesselModel());
  EXPECT_EQ(m.EquationStates(), (std::vector<std::string>{"r", "u"}));  // JSON's key order
  EXPECT_EQ(m.Equation("r"), "0.02-0.5*r+tau_n");
  EXPECT_FALSE(m.Equation("v"));
  EXPECT_EQ(m.Inputs(), (std::vector<std::string>{"tau_x", "tau_n"}));
  EXPECT_FALSE(m.Variables());
  EXPECT_EQ(m.Parameter("r.bias"), 0.02);
  EXPECT_EQ(m.Forces(), "waterjet");
  EXPECT_EQ(m.DelaySeconds(), 0.2);
  EXPECT_EQ(m.Calibration("yaw_bias"), "zigzag");
  EXPECT_TRUE(m.Calibration("choose").is_null());
  EXPECT_EQ(m.TrainSeconds(), 1.5);
}

TEST(ModelViewTest, AbsentKeysMeanNone) {
  const nlohmann::json bare = {{"vessel", nullptr}};
  const ModelView m(bare);
  EXPECT_EQ(m.Method("model"), "model");
  EXPECT_EQ(m.Vessel(), "");
  EXPECT_FALSE(m.IsVesselModel());  // a null vessel names none
  EXPECT_TRUE(m.Inputs().empty());
  EXPECT_EQ(m.Forces(), "");
  EXPECT_EQ(m.DelaySeconds(), 0.0);
  EXPECT_FALSE(m.LengthM());
  EXPECT_TRUE(m.Effects().empty());
  EXPECT_TRUE(m.Alternatives().empty());
  EXPECT_TRUE(m.Parameters().is_null());
  EXPECT_THROW(m.Equations(), InputError);
}

TEST(ModelViewTest, AMalformedModelNamesTheKey) {
  const nlohmann::json bad_vessel = {{"vessel", 3}};
  EXPECT_TRUE(ModelView(bad_vessel).IsVesselModel());
  EXPECT_THROW(ModelView(bad_vessel).VesselModelName(), InputError);
  const nlohmann::json bad_effects = {{"vessel", "kvlcc2"}, {"effects", "wind"}};
  EXPECT_THROW(ModelView(bad_effects).Effects(), InputError);
  const nlohmann::json bad_equation = {{"equations", {{"r", 1.0}}}};
  try {
    ModelView(bad_equation).Equations();
    FAIL() << "a number as an equation was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'r'"), std::string::npos) << e.what();
  }
}

TEST(ModelViewTest, EditsSetTheirKeysOnly) {
  nlohmann::json model = kEquationModel;
  ModelEdit edit(model);
  edit.SetEquation("r", "0.03-0.5*r+tau_n");
  edit.UpdateParameter("r.bias", 0.03);
  edit.UpdateParameter("u.bias", 1.0);  // the model has none: left out
  edit.SetCalibration("yaw_bias", {{"applied", true}});
  EXPECT_EQ(model["equations"]["r"], "0.03-0.5*r+tau_n");
  EXPECT_EQ(model["parameters"], (nlohmann::json{{"r.bias", 0.03}}));
  EXPECT_EQ(model["calibration"]["yaw_bias"]["applied"], true);
  EXPECT_EQ(model["equations"]["u"], kEquationModel["equations"]["u"]);
}

}  // namespace
}  // namespace usvid
