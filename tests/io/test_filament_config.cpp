// [[filament_type]], [[filaments]], [boundary], [[linker]], [[motor]], [[brancher]]:
// a valid config gives the typed values and defaults; every bad value is an InputError
// naming the dotted key.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/config.hpp"

namespace cortex {
namespace {

const std::string kValid = R"(
[compartments]
size = 500.0
shape = [2, 2, 2]

[[species]]
name = "GA"
copies = 1000

[[species]]
name = "AA"
copies = 10

[[species]]
name = "MY"
copies = 5

[[species]]
name = "ARP"
copies = 5

[[filament_type]]
name = "actin"
monomer_species = "GA"
plus_on = 11.6
plus_off = 1.4
minus_on = 1.3
minus_off = 0.8

[[filaments]]
count = 4
length = 200.0

[[filaments]]
type = "actin"
count = 7
length = 100.0
placement = "bundle"
center = [500.0, 500.0, 500.0]
direction = [0.0, 0.0, 2.0]
spacing = 12.0

[boundary]
shape = "box"
repulsion = 50.0

[[linker]]
species = "AA"
on_rate = 0.009
off_rate = 0.3

[[motor]]
name = "myosin"
species = "MY"
walk_rate = 0.2

[[brancher]]
species = "ARP"
rate = 0.0001
angle = 70.0
)";

Config parse(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return parseConfig(text, "test.toml", ".", overrides);
}

TEST(FilamentConfig, ValidConfigParsesWithValuesAndDefaults) {
  const Config c = parse(kValid);
  ASSERT_TRUE(c.filaments);
  const FilamentConfig& f = *c.filaments;
  ASSERT_EQ(f.types.size(), 1u);
  const FilamentType& t = f.types[0];
  EXPECT_EQ(t.name, "actin");
  EXPECT_EQ(t.monomer_species, "GA");
  EXPECT_EQ(t.monomer_species_index, 0);
  EXPECT_DOUBLE_EQ(t.plus_on, 11.6);
  EXPECT_DOUBLE_EQ(t.minus_off, 0.8);
  EXPECT_DOUBLE_EQ(t.monomer_size, 2.7);
  EXPECT_EQ(t.cylinder_monomers, 40);
  EXPECT_DOUBLE_EQ(t.bending_stiffness, 672.0);
  EXPECT_DOUBLE_EQ(t.nucleation_rate, 0.0);

  ASSERT_EQ(f.initial.size(), 2u);
  EXPECT_EQ(f.initial[0].type, "actin");
  EXPECT_EQ(f.initial[0].type_index, 0);
  EXPECT_EQ(f.initial[0].count, 4);
  EXPECT_EQ(f.initial[0].placement, FilamentInit::Placement::kRandom);
  EXPECT_FALSE(f.initial[0].region);
  EXPECT_EQ(f.initial[1].placement, FilamentInit::Placement::kBundle);
  EXPECT_TRUE(f.initial[1].direction.isApprox(Vec3::UnitZ()));
  EXPECT_TRUE(f.initial[1].center.isApprox(Vec3(500, 500, 500)));
  EXPECT_DOUBLE_EQ(f.initial[1].spacing, 12.0);
  EXPECT_FALSE(f.initial[1].mixed_polarity);
  EXPECT_TRUE(parse(kValid, {"filaments.1.polarity=\"mixed\""}).filaments->initial[1].mixed_polarity);

  ASSERT_TRUE(f.boundary);
  EXPECT_EQ(f.boundary->shape, BoundaryConfig::Shape::kBox);
  EXPECT_TRUE(f.boundary->min.isApprox(Vec3::Zero()));
  EXPECT_TRUE(f.boundary->max.isApprox(Vec3(1000, 1000, 1000)));  // the grid's box
  EXPECT_DOUBLE_EQ(f.boundary->repulsion, 50.0);
  EXPECT_DOUBLE_EQ(f.boundary->screening_length, 2.7);

  ASSERT_EQ(f.linkers.size(), 1u);
  EXPECT_EQ(f.linkers[0].name, "AA");  // defaults to the species
  EXPECT_EQ(f.linkers[0].species_index, 1);
  EXPECT_DOUBLE_EQ(f.linkers[0].on_rate, 0.009);
  EXPECT_DOUBLE_EQ(f.linkers[0].min_distance, 30.0);
  EXPECT_DOUBLE_EQ(f.linkers[0].max_distance, 40.0);
  EXPECT_DOUBLE_EQ(f.linkers[0].stiffness, 8.0);
  ASSERT_EQ(f.motors.size(), 1u);
  EXPECT_EQ(f.motors[0].name, "myosin");
  EXPECT_EQ(f.motors[0].species_index, 2);
  EXPECT_DOUBLE_EQ(f.motors[0].walk_rate, 0.2);
  EXPECT_DOUBLE_EQ(f.motors[0].stall_force, 90.0);
  EXPECT_DOUBLE_EQ(f.motors[0].min_distance, 175.0);
  ASSERT_EQ(f.branchers.size(), 1u);
  EXPECT_EQ(f.branchers[0].species_index, 3);
  EXPECT_EQ(f.branchers[0].filament_type, "actin");
  EXPECT_EQ(f.branchers[0].filament_type_index, 0);
  EXPECT_DOUBLE_EQ(f.branchers[0].angle, 70.0);
}

TEST(FilamentConfig, AbsentWithoutFilamentTypes) {
  const Config c = parse("[[species]]\nname = \"A\"\n");
  EXPECT_FALSE(c.filaments);
}

TEST(FilamentConfig, FilamentsAloneNeedNoSpeciesAndDefaultToTheGridBox) {
  const Config c = parse("[[filament_type]]\n[[filaments]]\ncount = 2\n");
  ASSERT_TRUE(c.filaments);
  EXPECT_EQ(c.filaments->types[0].name, "actin");
  EXPECT_EQ(c.filaments->types[0].monomer_species_index, -1);
  EXPECT_FALSE(c.filaments->boundary);
  EXPECT_EQ(c.filaments->initial[0].count, 2);
}

TEST(FilamentConfig, SphereBoundaryAndSeveralTypes) {
  const std::string text = kValid + R"(
[[filament_type]]
name = "microtubule"
monomer_size = 8.0
bending_stiffness = 2.0e5
)";
  const Config c = parse(text, {"boundary.shape=\"sphere\"", "boundary.center=[500.0, 500.0, 500.0]",
                                "boundary.radius=400.0", "filaments.0.type=\"microtubule\"",
                                "brancher.0.filament_type=\"actin\""});
  const FilamentConfig& f = *c.filaments;
  ASSERT_EQ(f.types.size(), 2u);
  EXPECT_EQ(f.initial[0].type_index, 1);
  EXPECT_EQ(f.boundary->shape, BoundaryConfig::Shape::kSphere);
  EXPECT_DOUBLE_EQ(f.boundary->radius, 400.0);
}

TEST(FilamentConfig, OverridesReachArraysOfTables) {
  const Config c = parse(kValid, {"filaments.0.count=5", "linker.0.stiffness=3.5",
                                  "filaments.0.region={ min = [100.0, 100.0, 100.0], max = [200.0, 300.0, 400.0] }"});
  EXPECT_EQ(c.filaments->initial[0].count, 5);
  EXPECT_DOUBLE_EQ(c.filaments->linkers[0].stiffness, 3.5);
  ASSERT_TRUE(c.filaments->initial[0].region);
  EXPECT_TRUE((*c.filaments->initial[0].region)[1].isApprox(Vec3(200, 300, 400)));
}

TEST(FilamentConfig, AClampedMinusEndIsAFixedOne) {
  const Config c = parse(kValid, {"filaments.1.clamped_minus_end=true"});
  EXPECT_TRUE(c.filaments->initial[1].clamped_minus_end);
  EXPECT_TRUE(c.filaments->initial[1].fixed_minus_end);
  EXPECT_FALSE(c.filaments->initial[0].clamped_minus_end);
  EXPECT_FALSE(c.filaments->initial[0].fixed_minus_end);
}

struct BadOverride {
  std::string set;  // a --set assignment on kValid
  std::string key;  // expected in the message
};

class BadFilamentValues : public ::testing::TestWithParam<BadOverride> {};

TEST_P(BadFilamentValues, AreInputErrorsNamingTheKey) {
  try {
    parse(kValid, {GetParam().set});
    FAIL() << GetParam().set << " was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(GetParam().key), std::string::npos) << message;
    EXPECT_NE(message.find("test.toml"), std::string::npos) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(
    FilamentConfig, BadFilamentValues,
    ::testing::Values(
        BadOverride{"filament_type.0.monomer_size=-1.0", "filament_type.0.monomer_size"},
        BadOverride{"filament_type.0.monomer_size=nan", "filament_type.0.monomer_size"},
        BadOverride{"filament_type.0.plus_on=inf", "filament_type.0.plus_on"},
        // Past the default bound of 1e300 the message names that bound ("must be >= 0"
        // stated the wrong problem).
        BadOverride{"filament_type.0.plus_on=7.6e301", "filament_type.0.plus_on: must be in [0, 1e+300]"},
        BadOverride{"filament_type.0.cylinder_monomers=0", "filament_type.0.cylinder_monomers"},
        BadOverride{"filament_type.0.cylinder_monomers=2.5", "filament_type.0.cylinder_monomers"},
        BadOverride{"filament_type.0.bending_stiffness=-1.0", "filament_type.0.bending_stiffness"},
        BadOverride{"filament_type.0.stretching_stiffness=0.0", "filament_type.0.stretching_stiffness"},
        BadOverride{"filament_type.0.excluded_volume_distance=0.0", "filament_type.0.excluded_volume_distance"},
        BadOverride{"filament_type.0.monomer_species=\"nope\"", "filament_type.0.monomer_species"},
        BadOverride{"filament_type.0.name=\"a b\"", "filament_type.0.name"},
        BadOverride{"filament_type.0.monomer_sise=3.0", "filament_type.0.monomer_sise"},
        BadOverride{"filaments.0.count=-1", "filaments.0.count"},
        BadOverride{"filaments.0.length=1.0", "filaments.0.length"},
        BadOverride{"filaments.0.length=2000.0", "filaments.0.length"},  // > box diagonal 1732 nm
        BadOverride{"filaments.0.type=\"myosin\"", "filaments.0.type"},
        BadOverride{"filaments.0.placement=\"grid\"", "filaments.0.placement"},
        BadOverride{"filaments.0.spacing=5.0", "filaments.0.spacing"},
        BadOverride{"filaments.0.region={ min = [0.0, 0.0, 0.0], max = [10.0, -1.0, 10.0] }", "filaments.0.region"},
        BadOverride{"filaments.0.region={ min = [0.0, 0.0, 0.0] }", "filaments.0.region.max"},
        BadOverride{"filaments.1.direction=[0.0, 0.0, 0.0]", "filaments.1.direction"},
        BadOverride{"filaments.1.direction=[0.0, 1.0]", "filaments.1.direction"},
        BadOverride{"filaments.1.spacing=0.0", "filaments.1.spacing"},
        BadOverride{"filaments.1.polarity=\"both\"", "filaments.1.polarity"},
        BadOverride{"filaments.0.polarity=\"mixed\"", "filaments.0.polarity"},
        BadOverride{"filaments.1.region={ min = [0.0, 0.0, 0.0], max = [1.0, 1.0, 1.0] }", "filaments.1.region"},
        BadOverride{"filaments.1.lenght=3.0", "filaments.1.lenght"},
        BadOverride{"boundary.shape=\"cube\"", "boundary.shape"},
        BadOverride{"boundary.max=[0.0, 1000.0, 1000.0]", "boundary.max"},
        BadOverride{"boundary.radius=5.0", "boundary.radius"},
        BadOverride{"boundary.shape=\"sphere\"", "boundary.center"},
        BadOverride{"boundary.screening_length=0.0", "boundary.screening_length"},
        BadOverride{"boundary.repulsion=-1.0", "boundary.repulsion"},
        BadOverride{"linker.0.max_distance=10.0", "linker.0.max_distance"},
        BadOverride{"linker.0.min_distance=-1.0", "linker.0.min_distance"},
        BadOverride{"linker.0.species=\"nope\"", "linker.0.species"},
        BadOverride{"linker.0.species=\"GA\"", "linker.0.species"},  // the monomers
        BadOverride{"linker.0.on_rate=-1.0", "linker.0.on_rate"},
        BadOverride{"linker.0.site_spacing=0", "linker.0.site_spacing"},
        BadOverride{"linker.0.stiffness=inf", "linker.0.stiffness"},
        BadOverride{"motor.0.stall_force=0.0", "motor.0.stall_force"},
        BadOverride{"motor.0.hill_alpha=-0.2", "motor.0.hill_alpha"},
        BadOverride{"motor.0.name=\"AA\"", "motor.0.name"},      // the linker's name
        BadOverride{"motor.0.species=\"AA\"", "motor.0.species"},  // the linker's species
        BadOverride{"motor.0.max_distance=175.0", "motor.0.max_distance"},
        BadOverride{"motor.0.site_spacing=-3", "motor.0.site_spacing"},
        BadOverride{"motor.0.heads_min=10", "motor.0.heads_max"},  // one without the other
        BadOverride{"motor.0.head_load=nan", "motor.0.head_load"},
        BadOverride{"motor.0.head_load=-1.0", "motor.0.head_load"},
        BadOverride{"motor.0.head_binding_rate=0.0", "motor.0.head_binding_rate"},
        BadOverride{"brancher.0.angle=180.0", "brancher.0.angle"},
        BadOverride{"brancher.0.angle=0.0", "brancher.0.angle"},
        BadOverride{"brancher.0.filament_type=\"nope\"", "brancher.0.filament_type"},
        BadOverride{"brancher.0.rate=-1.0", "brancher.0.rate"}));

void expectInputError(const std::string& text, const std::string& key) {
  try {
    parse(text);
    FAIL() << "accepted:\n" << text;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

TEST(FilamentConfig, FilamentTablesWithoutFilamentTypeAreErrors) {
  const std::string species = "[[species]]\nname = \"A\"\n";
  expectInputError(species + "[[linker]]\nspecies = \"A\"\n", "linker");
  expectInputError(species + "[[motor]]\nspecies = \"A\"\n", "motor");
  expectInputError(species + "[[brancher]]\nspecies = \"A\"\n", "brancher");
  expectInputError(species + "[[filaments]]\ncount = 1\n", "filaments");
  expectInputError(species + "[boundary]\nshape = \"box\"\n", "boundary");
}

TEST(FilamentConfig, CombinationsAreChecked) {
  // Growth needs the monomers' species.
  expectInputError("[[filament_type]]\nplus_on = 1.0\n", "filament_type.0.monomer_species");
  expectInputError("[[filament_type]]\nmonomer_species = \"GA\"\n", "filament_type.0.monomer_species");
  // Several types: names are required and unique; references name one.
  expectInputError("[[filament_type]]\nname = \"a\"\n[[filament_type]]\n", "filament_type.1.name");
  expectInputError("[[filament_type]]\nname = \"a\"\n[[filament_type]]\nname = \"a\"\n", "filament_type.1.name");
  expectInputError("[[filament_type]]\nname = \"a\"\n[[filament_type]]\nname = \"b\"\n[[filaments]]\n",
                   "filaments.0.type");
  // Longer than the sphere's diameter.
  expectInputError("[[filament_type]]\n[boundary]\nshape = \"sphere\"\ncenter = [0.0, 0.0, 0.0]\nradius = 50.0\n"
                   "[[filaments]]\nlength = 120.0\n",
                   "filaments.0.length");
  // A sphere needs its radius.
  expectInputError("[[filament_type]]\n[boundary]\nshape = \"sphere\"\ncenter = [0.0, 0.0, 0.0]\n", "boundary.radius");
}

}  // namespace
}  // namespace cortex
