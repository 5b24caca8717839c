// `cortex import-medyan`: MEDYAN input files written here (both spellings of the format,
// per MEDYAN's public manual) translate into a config that cortex accepts, with the unit
// conversions asserted numerically, and what cannot be translated is listed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "app/cli_helpers.hpp"
#include "core/error.hpp"
#include "io/config.hpp"
#include "io/medyan_import.hpp"

namespace cortex {
namespace {

using cli_test::TempDir;
using cli_test::writeFile;

// Copies per µM in one 500 nm compartment (0.125 fL).
constexpr double kPerMicromolar = 602.214076 * 0.125;

// The legacy colon spelling of the example files, with comments and a bare-word key.
const char* kSystemColon = R"(# a system file in the colon form
NX:                          2
NY:                          2
NZ:                          1
COMPARTMENTSIZEX:            500.0
COMPARTMENTSIZEY:            500.0
COMPARTMENTSIZEZ:            500.0
BOUNDARYSHAPE:               CUBIC
BOUNDARYDIAMETER:
RUNTIME:                     3.0
SNAPSHOTTIME:                0.5
MINIMIZATIONTIME:            0.05
NEIGHBORLISTTIME:            0.05
CHEMISTRYFILE:               chem.txt
NUMFILAMENTS:                12
FILAMENTLENGTH:              2
FILAMENTTYPE:                0
FILAMENTFILE:
FSTRETCHINGFFTYPE:           HARMONIC
FSTRETCHINGK:                90.0
FBENDINGFFTYPE:              COSINE
FBENDINGK:                   600.0
FBENDINGTHETA:               0.0
VOLUMEFFTYPE:                integral
VOLUMECUTOFF:                135.0
VOLUMEK:                     8.57
DFPOLYMERIZATIONTYPE:        BROWRATCHET
DFPOLYMERIZATIONLEN:         2.7
MSTRETCHINGFFTYPE:           HARMONIC
MSTRETCHINGK:                2.0
NUMMOTORHEADSMIN:            10
NUMMOTORHEADSMAX:            20
MOTORSTEPSIZE:               6.0
DMUNBINDINGTYPE:             LOWDUTYCATCH
DMUNBINDINGFORCE:            12.0
DMWALKINGTYPE:               LOWDUTYSTALL
DMWALKINGFORCE:              80.0
LSTRETCHINGFFTYPE:           HARMONIC
LSTRETCHINGK:                7.0
DLUNBINDINGTYPE:             SLIP
DLUNBINDINGLEN:              0.3
BOUNDARYFFTYPE:              REPULSIONEXP
BOUNDARYCUTOFF:              300.0
BOUNDARYINTERACTIONK:        40.0
BOUNDARYSCREENLENGTH:        2.5
MONOMERSIZE:                 2.7
CYLINDERSIZE:                108.0
CONJUGATEGRADIENT:           POLAKRIBIERE
GRADIENTTOLERANCE:           0.5
MAXDISTANCE:                 2.0
LAMBDAMAX:                   0.01
CALGORITHM:                  NRM
NUMBINDINGSITES:             4
NUMFILAMENTTYPES:            1
PROJECTIONTYPE:              STRAIGHT
SPECIALPROTOCOL:             MAKELINKERSSTATIC 5.0
allow-same-filament-pair-binding false
)";

// The s-expression spelling of the manual, with a reaction over two lines and a nested group.
const char* kChemistrySexpr = R"(; a chemistry file in the s-expression form
(SPECIESDIFFUSING AD 3000 20.0e6 0.0 0.0 REG)
(SPECIESDIFFUSING LD 200 2.0e6 0.0 0.0 REG)
(SPECIESDIFFUSING MD 20 0.2e6 4.0 0.0 REG)
(SPECIESDIFFUSING X 100 1.0e6 0.0 0.0 REG)
(SPECIESDIFFUSING Y 0 1.0e6 0.0 0.0 REG)
(SPECIESFILAMENT FA 0)
(SPECIESPLUSEND PA 0)
(SPECIESMINUSEND MA 0)
(SPECIESBOUND LEA 0)
(SPECIESBOUND MEA 0)
(SPECIESLINKER LA 0)
(SPECIESMOTOR MOA 0)
(LINKERBINDINGSITE LEA 0)
(MOTORBINDINGSITE MEA 0)
(POLYMERIZATIONREACTION 0 AD:DIFFUSING + PA:PLUSEND -> FA:FILAMENT + PA:PLUSEND 0.15)
(POLYMERIZATIONREACTION 0 AD:DIFFUSING + MA:MINUSEND -> FA:FILAMENT + MA:MINUSEND 0.02)
(DEPOLYMERIZATIONREACTION 0 FA:FILAMENT + PA:PLUSEND -> AD:DIFFUSING + PA:PLUSEND 1.5)
(DEPOLYMERIZATIONREACTION 0 FA:FILAMENT + MA:MINUSEND -> AD:DIFFUSING + MA:MINUSEND 0.9)
(LINKERREACTION 0 LEA:BOUND:1 + LEA:BOUND:2 + LD:DIFFUSING <-> LA:LINKER:1 + LA:LINKER:2
    0.02 0.25 30.0 40.0)
(MOTORREACTION 0 MEA:BOUND:1 + MEA:BOUND:2 + MD:DIFFUSING <-> MOA:MOTOR:1 + MOA:MOTOR:2
    0.1 1.5 170.0 220.0)
(MOTORWALKINGREACTION 0 MOA:MOTOR:N + MEA:BOUND:N+1 -> MOA:MOTOR:N+1 + MEA:BOUND:N 0.3)
(GENREACTION X:DIFFUSING + X:DIFFUSING -> Y:DIFFUSING 0.004)
(GENREACTION Y:DIFFUSING -> X:DIFFUSING 2.0)
(AGINGREACTION 0 FA:FILAMENT -> FA:FILAMENT 0.1)
(membrane cell (area-k 400) (bending-k 50))
)";

struct Files {
  TempDir dir;
  std::filesystem::path system, chemistry;
  Files(const std::string& system_text, const std::string& chemistry_text) {
    system = dir / "system.txt";
    chemistry = dir / "chem.txt";
    writeFile(system, system_text);
    writeFile(chemistry, chemistry_text);
  }
};

bool listed(const std::vector<std::string>& list, const std::string& needle) {
  return std::any_of(list.begin(), list.end(), [&](const std::string& s) { return s.find(needle) != std::string::npos; });
}

TEST(MedyanImport, TranslatesBothSpellingsWithUnitConversions) {
  Files files(kSystemColon, kChemistrySexpr);
  const MedyanImport m = importMedyan(files.system, std::nullopt);  // CHEMISTRYFILE found beside the system file
  const Config c = parseConfig(m.toml, "imported.toml", files.dir.path(), {});

  EXPECT_DOUBLE_EQ(c.simulation.end_time, 3.0);
  EXPECT_DOUBLE_EQ(c.simulation.chemistry_window, 0.05);
  EXPECT_DOUBLE_EQ(c.simulation.snapshot_interval, 0.5);
  EXPECT_DOUBLE_EQ(c.mechanics.force_tolerance, 0.5);
  EXPECT_DOUBLE_EQ(c.mechanics.max_step, 2.0);
  ASSERT_TRUE(c.chemistry);
  EXPECT_DOUBLE_EQ(c.chemistry->grid.size, 500.0);
  EXPECT_EQ(c.chemistry->grid.shape[0], 2);
  EXPECT_EQ(c.chemistry->grid.shape[2], 1);
  ASSERT_EQ(c.chemistry->species.size(), 5u);
  EXPECT_EQ(c.chemistry->species[0].name, "AD");
  EXPECT_DOUBLE_EQ(c.chemistry->species[0].diffusion, 20.0e6);  // nm²/s in both
  EXPECT_EQ(c.chemistry->initial_copies[0], 3000);
  EXPECT_EQ(c.chemistry->initial_copies[2], 20);

  ASSERT_TRUE(c.filaments);
  const FilamentConfig& f = *c.filaments;
  ASSERT_EQ(f.types.size(), 1u);
  const FilamentType& t = f.types[0];
  EXPECT_EQ(t.monomer_species, "AD");
  EXPECT_EQ(t.cylinder_monomers, 40);
  EXPECT_DOUBLE_EQ(t.stretching_stiffness, 90.0);
  EXPECT_DOUBLE_EQ(t.bending_stiffness, 600.0);
  EXPECT_DOUBLE_EQ(t.excluded_volume_distance, 3.78);  // (2π 8.57 pN·nm³ / 1 pN)^(1/3)
  EXPECT_DOUBLE_EQ(t.excluded_volume_stiffness, 10.0);
  // Per-copy rates in one compartment x N_A V = per µM.
  EXPECT_NEAR(t.plus_on, 0.15 * kPerMicromolar, 1e-9);
  EXPECT_NEAR(t.minus_on, 0.02 * kPerMicromolar, 1e-9);
  EXPECT_NEAR(t.plus_on, 11.2915, 1e-3);
  EXPECT_DOUBLE_EQ(t.plus_off, 1.5);
  EXPECT_DOUBLE_EQ(t.minus_off, 0.9);
  ASSERT_EQ(f.initial.size(), 1u);
  EXPECT_EQ(f.initial[0].count, 12);
  EXPECT_DOUBLE_EQ(f.initial[0].length, 216.0);  // 2 cylinders of 108 nm
  ASSERT_TRUE(f.boundary);
  // CUBIC: walls 25 nm inside the grid's faces (MEDYAN's manual).
  EXPECT_EQ(f.boundary->min, Vec3(25.0, 25.0, 25.0));
  EXPECT_EQ(f.boundary->max, Vec3(975.0, 975.0, 475.0));
  EXPECT_DOUBLE_EQ(f.boundary->repulsion, 40.0);
  EXPECT_DOUBLE_EQ(f.boundary->screening_length, 2.5);

  ASSERT_EQ(f.linkers.size(), 1u);
  const LinkerType& l = f.linkers[0];
  EXPECT_EQ(l.species, "LD");
  EXPECT_NEAR(l.on_rate, 0.02 * kPerMicromolar, 1e-9);
  EXPECT_NEAR(l.on_rate, 1.50554, 1e-4);
  EXPECT_DOUBLE_EQ(l.off_rate, 0.25);
  EXPECT_DOUBLE_EQ(l.min_distance, 30.0);
  EXPECT_DOUBLE_EQ(l.max_distance, 40.0);
  EXPECT_DOUBLE_EQ(l.stiffness, 7.0);
  EXPECT_DOUBLE_EQ(l.slip_length, 0.3);
  EXPECT_EQ(l.site_spacing, 10);  // 4 sites per 40-monomer cylinder

  ASSERT_EQ(f.motors.size(), 1u);
  const MotorType& mo = f.motors[0];
  EXPECT_EQ(mo.species, "MD");
  EXPECT_NEAR(mo.on_rate, 0.1 * kPerMicromolar, 1e-9);
  EXPECT_DOUBLE_EQ(mo.off_rate, 1.5);
  // Walking from binding site to binding site (27 nm) at the speed of 6 nm head steps.
  EXPECT_DOUBLE_EQ(mo.step_size, 27.0);
  EXPECT_NEAR(mo.walk_rate, 0.3 * 6.0 / 27.0, 1e-12);
  EXPECT_DOUBLE_EQ(mo.min_distance, 170.0);
  EXPECT_DOUBLE_EQ(mo.stiffness, 2.0);
  EXPECT_DOUBLE_EQ(mo.stall_force, 80.0);
  EXPECT_DOUBLE_EQ(mo.catch_force, 12.0);
  EXPECT_EQ(mo.heads_min, 10);
  EXPECT_EQ(mo.heads_max, 20);
  EXPECT_DOUBLE_EQ(mo.head_binding_rate, 0.3);

  // General reactions: order 2 per copy -> x N_A V; order 1 unchanged.
  ASSERT_EQ(c.chemistry->reactions.size(), 2u);
  EXPECT_NEAR(c.chemistry->reactions[0].rate, 0.004 * kPerMicromolar, 1e-9);
  EXPECT_EQ(c.chemistry->reactions[0].order(), 2);
  EXPECT_DOUBLE_EQ(c.chemistry->reactions[1].rate, 2.0);

  // What could not be translated is listed, with file and line.
  for (const char* item : {"system.txt:26: VOLUMEFFTYPE", "SPECIALPROTOCOL", "LAMBDAMAX", "RELEASETIME 4",
                           "AGINGREACTION", "chem.txt:28: membrane"})
    EXPECT_TRUE(listed(m.untranslated, item)) << item;
  // ... and what was, never in both lists.
  for (const char* item : {"LINKERREACTION", "NUMMOTORHEADSMIN", "MOTORWALKINGREACTION", "GENREACTION"})
    EXPECT_TRUE(listed(m.translated, item)) << item;
  EXPECT_FALSE(listed(m.untranslated, "LINKERREACTION"));
  EXPECT_FALSE(listed(m.untranslated, "allow-same-filament"));
  EXPECT_FALSE(listed(m.untranslated, "BOUNDARYDIAMETER"));  // empty value: not set
  EXPECT_NE(m.toml.find("# Not translated"), std::string::npos);
}

TEST(MedyanImport, SphericalBoundaryAndBulkSpecies) {
  Files files(R"((NX 2) (NY 2) (NZ 2)
(COMPARTMENTSIZEX 400) (COMPARTMENTSIZEY 400) (COMPARTMENTSIZEZ 400)
(BOUNDARYSHAPE SPHERICAL) (BOUNDARYDIAMETER 700)
(RUNTIME 1.0))",
              "SPECIESBULK: B 100 0.0 0.0 REG\nSPECIESDIFFUSING: A 10 1e6 0.0 0.0 REG\n"
              "BULKREACTION: B:BULK -> A:DIFFUSING 0.5\n");
  const MedyanImport m = importMedyan(files.system, files.chemistry);
  const Config c = parseConfig(m.toml, "imported.toml", files.dir.path(), {});
  EXPECT_DOUBLE_EQ(c.chemistry->grid.size, 400.0);
  EXPECT_TRUE(listed(m.untranslated, "SPECIESBULK B"));
  EXPECT_FALSE(c.filaments);  // no filaments: the boundary is for filaments only
}

void expectInputError(const std::string& system, const std::string& chemistry, const std::string& message) {
  Files files(system, chemistry);
  try {
    importMedyan(files.system, files.chemistry);
    ADD_FAILURE() << "no error; expected " << message;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

const char* kGeometry = "NX: 1\nNY: 1\nNZ: 1\nCOMPARTMENTSIZEX: 500\nCOMPARTMENTSIZEY: 500\nCOMPARTMENTSIZEZ: 500\n";

TEST(MedyanImport, InvalidInputNamesFileAndLine) {
  expectInputError("NX: 1\n(NY 1\nNZ: 1\n", "", "system.txt:2: '(' is never closed");
  expectInputError("NX: 1\nNY: 1)\n", "", "system.txt:2: unexpected ')'");
  expectInputError("NX: 1\n", "", "NX, NY, NZ and COMPARTMENTSIZEX/Y/Z are required");
  expectInputError(std::string(kGeometry) + "RUNTIME: ten\n", "", "system.txt:7: RUNTIME: the value must be a number");
  expectInputError("NX: 1\nNY: 1\nNZ: 1\nCOMPARTMENTSIZEX: 500\nCOMPARTMENTSIZEY: 250\nCOMPARTMENTSIZEZ: 500\n", "",
                   "cortex's compartments are cubes");
  expectInputError(kGeometry, "SPECIESDIFFUSING: A 10 1e6 0 0 REG\nGENREACTION: A:DIFFUSING -> Q:DIFFUSING 1.0\n",
                   "chem.txt:2: GENREACTION: species 'Q' is not defined");
  expectInputError(kGeometry, "SPECIESDIFFUSING: A many 1e6 0 0 REG\n", "chem.txt:1: SPECIESDIFFUSING: COPYNUMBER");
  // Counts too large for a copy number, or not whole: they were written as
  // -9223372036854775808, or truncated (2.5 as 2), and the import exited 0.
  expectInputError(kGeometry, "SPECIESDIFFUSING: A 1e300 1e6 0 0 REG\n",
                   "chem.txt:1: SPECIESDIFFUSING COPYNUMBER must be a whole number from 0 to 2e9, got 1e+300");
  expectInputError(std::string(kGeometry) + "NUMFILAMENTS: 30\nNUMFILAMENTS: 2.5\n", "",
                   "system.txt:8: NUMFILAMENTS must be a whole number from 0 to 2e9, got 2.5");
  expectInputError(kGeometry,
                   "SPECIESDIFFUSING: A 10 1e6 0 0 REG\nSPECIESPLUSEND: P 0\n"
                   "POLYMERIZATIONREACTION: 0 A:DIFFUSING P:PLUSEND -> A:DIFFUSING 1\n",
                   "chem.txt:3: POLYMERIZATIONREACTION: expected '->'");
  // Values that translated to configs `cortex check` then refused, naming the written
  // TOML's lines (exit 0 from the import), or to another model (0 sites per cylinder
  // became a site on every monomer: 169 bound linkers in 1 s against 8).
  const std::string species = "SPECIESDIFFUSING: A 10 1e6 0 0 REG\n";
  expectInputError(std::string(kGeometry) + "RUNTIME: -1\n", species, "system.txt:7: RUNTIME -1: must be > 0 s");
  expectInputError(std::string(kGeometry) + "SNAPSHOTTIME: 0\n", species, "system.txt:7: SNAPSHOTTIME 0: must be > 0 s");
  expectInputError(std::string(kGeometry) + "MINIMIZATIONTIME: 0\n", species,
                   "system.txt:7: MINIMIZATIONTIME 0: must be > 0 s");
  expectInputError(std::string(kGeometry) + "MONOMERSIZE: 0\n", species, "system.txt:7: MONOMERSIZE 0: must be > 0 nm");
  expectInputError(std::string(kGeometry) + "NUMBINDINGSITES: 0\n", species,
                   "system.txt:7: NUMBINDINGSITES 0: a cylinder of 40 monomers holds 1 to 40 binding sites");
  // What no keyword check catches is caught in the translated config, before writing.
  expectInputError("NX: 100000000\nNY: 1\nNZ: 1\nCOMPARTMENTSIZEX: 500\nCOMPARTMENTSIZEY: 500\nCOMPARTMENTSIZEZ: 500\n",
                   species, "they translate to a config cortex cannot run (the translated config:");
  expectInputError(kGeometry, "", "compartments: has no effect without [[species]]");
  Files missing(kGeometry, "");
  EXPECT_THROW(importMedyan(missing.dir / "nonexistent.txt", std::nullopt), InputError);
  EXPECT_THROW(importMedyan(missing.system, std::nullopt), InputError);  // no CHEMISTRYFILE
}

TEST(MedyanImport, CommandWritesAConfigThatCheckAccepts) {
  Files files(kSystemColon, kChemistrySexpr);
  const auto out = files.dir / "imported.toml";
  const auto r = cli_test::runCortex({"import-medyan", files.system.string(), files.chemistry.string(), "-o", out.string()},
                                     files.dir.path());
  ASSERT_EQ(r.exit_code, 0) << cli_test::describe(r);
  EXPECT_NE(r.out.find("Not translated ("), std::string::npos);
  EXPECT_NE(r.out.find("VOLUMEK"), std::string::npos);
  const auto check = cli_test::runCortex({"check", out.string()}, files.dir.path());
  EXPECT_EQ(check.exit_code, 0) << cli_test::describe(check);
  // A second import into the same file needs --overwrite.
  const auto again = cli_test::runCortex(
      {"import-medyan", files.system.string(), files.chemistry.string(), "-o", out.string()}, files.dir.path());
  EXPECT_EQ(again.exit_code, 2) << cli_test::describe(again);
  // Invalid input: exit 2 with file and line.
  writeFile(files.system, "NX: 1\n(NY 1\n");
  const auto bad = cli_test::runCortex({"import-medyan", files.system.string(), "-o", (files.dir / "x.toml").string()},
                                       files.dir.path());
  EXPECT_EQ(bad.exit_code, 2) << cli_test::describe(bad);
  EXPECT_NE(bad.err.find("system.txt:2:"), std::string::npos) << bad.err;
  // An output path that cannot be written is the command line's error (exit 2), not a
  // failed run (exit 1).
  writeFile(files.system, kSystemColon);
  for (const std::filesystem::path& to : {files.dir / "no-such-folder" / "x.toml", files.dir.path()}) {
    const auto unwritable = cli_test::runCortex(
        {"import-medyan", files.system.string(), files.chemistry.string(), "-o", to.string(), "--overwrite"},
        files.dir.path());
    EXPECT_EQ(unwritable.exit_code, 2) << cli_test::describe(unwritable);
    EXPECT_NE(unwritable.err.find(to.string() + ": cannot write the config there"), std::string::npos)
        << cli_test::describe(unwritable);
  }
}

// The repository's translated example (examples/medyan/) stays importable and valid.
TEST(MedyanImport, RepositoryExampleTranslatesAndChecks) {
  const auto dir = cli_test::sourceDir() / "examples/medyan/50filaments_motor_linker";
  const MedyanImport m = importMedyan(dir / "systeminput.txt", std::nullopt);
  const Config c = parseConfig(m.toml, "imported.toml", dir, {});
  ASSERT_TRUE(c.filaments);
  EXPECT_EQ(c.filaments->initial[0].count, 30);
  EXPECT_NEAR(c.filaments->linkers[0].on_rate, 0.7528, 1e-4);
  EXPECT_NEAR(c.filaments->motors[0].on_rate, 15.06, 1e-2);
  EXPECT_NEAR(c.filaments->motors[0].walk_rate, 0.2 * 6.0 / 27.0, 1e-12);
  EXPECT_DOUBLE_EQ(c.filaments->types[0].excluded_volume_distance, 3.78);
  EXPECT_EQ(c.filaments->motors[0].heads_min, 15);
  EXPECT_EQ(c.filaments->motors[0].heads_max, 30);
}

}  // namespace
}  // namespace cortex
