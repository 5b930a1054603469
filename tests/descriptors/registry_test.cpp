#include "descriptors/descriptor_registry.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace radarpr {
namespace {

// Records the parameters it was built with, so tests can see what the registry resolved.
class FakeDescriptor : public Descriptor {
 public:
  explicit FakeDescriptor(ParameterValues values) : values_(std::move(values)) {}
  DescriptorValue extract(const PolarImage&) const override { return {}; }
  double distance(const DescriptorValue&, const DescriptorValue&) const override { return 0.0; }
  bool rotation_invariant() const override { return false; }
  DescriptorShape shape(const ScanGeometry&) const override { return {0, 0}; }
  ParameterValues values_;
};

DescriptorInfo fake_info() {
  DescriptorInfo info;
  info.name = "fake";
  info.parameters = {
      {.name = "z_q", .kind = ParameterKind::number, .default_value = 6.0, .minimum = 0.0},
      {.name = "kernel",
       .kind = ParameterKind::choice,
       .default_value = std::string("gaussian"),
       .choices = {"gaussian", "box"}},
      {.name = "alpha",
       .kind = ParameterKind::integer,
       .default_value = std::int64_t{50},
       .minimum = 1.0},
  };
  info.create = [](const ParameterValues& values) {
    return std::make_unique<FakeDescriptor>(values);
  };
  return info;
}

DescriptorRegistry fake_registry() {
  DescriptorRegistry registry;
  registry.add(fake_info());
  return registry;
}

TEST(DescriptorRegistry, DefaultsGiveTheBareName) {
  const auto instance = fake_registry().create("fake", nlohmann::json::object());
  EXPECT_EQ(instance.id, "fake");
  EXPECT_EQ(instance.parameters.number("z_q"), 6.0);
  EXPECT_EQ(instance.parameters.choice("kernel"), "gaussian");
  EXPECT_EQ(instance.parameters.integer("alpha"), 50);
}

TEST(DescriptorRegistry, IdListsChangedParametersSortedByKey) {
  const auto instance =
      fake_registry().create("fake", nlohmann::json{{"z_q", 3}, {"kernel", "box"}, {"alpha", 50}});
  EXPECT_EQ(instance.id, "fake:kernel=box,z_q=3");  // alpha = default: left out
  const auto* fake = dynamic_cast<const FakeDescriptor*>(instance.descriptor.get());
  ASSERT_NE(fake, nullptr);
  EXPECT_EQ(fake->values_.number("z_q"), 3.0);
}

TEST(DescriptorRegistry, IdRoundTripsThroughCreateFromId) {
  const auto registry = fake_registry();
  const auto parsed = registry.create_from_id("fake:z_q=3,kernel=box,alpha=40");
  EXPECT_EQ(parsed.id, "fake:alpha=40,kernel=box,z_q=3");
  EXPECT_EQ(registry.create_from_id(parsed.id).id, parsed.id);
  EXPECT_EQ(registry.create_from_id("fake:z_q=6.0").id, "fake");
}

TEST(DescriptorRegistry, RejectsUnknownNamesParametersAndBadValues) {
  const auto registry = fake_registry();
  EXPECT_THROW(registry.create("nope", nlohmann::json::object()), std::invalid_argument);
  try {
    registry.create("fake", nlohmann::json{{"zq", 3}});
    FAIL() << "expected a ParameterError";
  } catch (const ParameterError& error) {
    EXPECT_EQ(error.parameter(), "zq");
    EXPECT_NE(std::string(error.what()).find("alpha, kernel, z_q"), std::string::npos)
        << error.what();
  }
  EXPECT_THROW(registry.create("fake", nlohmann::json{{"kernel", 3}}), ParameterError);
  EXPECT_THROW(registry.create("fake", nlohmann::json::array()), std::invalid_argument);
  EXPECT_THROW(registry.create_from_id("fake:z_q"), std::invalid_argument);
  EXPECT_THROW(registry.create_from_id("fake:z_q=1,z_q=2"), ParameterError);
  EXPECT_THROW(registry.create_from_id("fake:alpha=1.5"), ParameterError);
}

TEST(DescriptorRegistry, RejectsDuplicatesAndInvalidDefaults) {
  auto registry = fake_registry();
  EXPECT_THROW(registry.add(fake_info()), std::invalid_argument);
  auto bad = fake_info();
  bad.name = "bad";
  bad.parameters[0].default_value = -1.0;  // below its own minimum
  EXPECT_THROW(registry.add(bad), std::invalid_argument);
}

}  // namespace
}  // namespace radarpr
