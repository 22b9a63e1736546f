// The bulk-data deck as limber reads it: the supported cards, checked field by field, each
// with the place it came from (docs/bulk-data.md lists the cards and their fields). Ids are
// the deck's; references between cards are resolved later (deck_to_fe.h), where a missing
// property, material, grid or coordinate system is an error at the referring field.
// Units are the deck's own (limber assumes they are consistent, and SI in a case file).
#pragma once

#include <Eigen/Core>
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "fe/fe_model.h"

namespace limber::bulkdata {

// CORD2R / CORD2C / CORD2S: three points A (origin), B (on local z), C (in the local x-z
// plane), given in the coordinate system `reference` (0: basic).
struct CoordinateSystemCard {
  enum class Type { kRectangular, kCylindrical, kSpherical };
  int id = 0;
  Type type = Type::kRectangular;
  int reference = 0;
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  SourceLocation where;
  SourceLocation reference_where;  // the RID field
};

struct GridCard {
  int id = 0;
  int position_system = 0;      // CP
  Eigen::Vector3d position;     // X1-X3 in CP
  int displacement_system = 0;  // CD
  std::string permanent_spc;    // PS, component digits ("" when blank)
  SourceLocation where;
  SourceLocation cp_where, cd_where;
};

// MAT1 with E and nu (the two of E, G, nu given fix the third: G = E / (2 (1 + nu))).
struct MaterialCard {
  int id = 0;
  fe::Material material;  // name "MAT1 <id>"; rho as given (WTMASS applied later)
  SourceLocation where;
};

// PBAR, PBARL (section from its dimensions) or PBEAM (constant section).
struct BeamPropertyCard {
  int id = 0;
  std::string card;  // "PBAR", "PBARL", "PBEAM"
  int material = 0;
  fe::BeamSection section;
  bool timoshenko = false;
  SourceLocation where, material_where;
};

// PSHELL with one material for membrane, bending and transverse shear.
struct ShellPropertyCard {
  int id = 0;
  int material = 0;
  double thickness = 0.0;       // T
  double bending_ratio = 1.0;   // 12I/T^3
  double shear_ratio = fe::kShellShearFactor;  // TS/T
  double nonstructural_mass = 0.0;             // NSM per area
  bool no_shear_material = false;              // MID3 blank (NASTRAN: no shear flexibility)
  SourceLocation where, material_where;
};

// CBAR or CBEAM: orientation from G0 (a grid) or the vector X in GA's displacement system
// (or basic, with OFFT 'B..').
struct BeamCard {
  int id = 0;
  std::string card;  // "CBAR", "CBEAM"
  int property = 0;
  std::array<int, 2> grids{};
  std::optional<int> orientation_grid;  // G0
  Eigen::Vector3d orientation = Eigen::Vector3d::Zero();
  bool orientation_in_basic = false;
  SourceLocation where, property_where;
  std::array<SourceLocation, 2> grid_where;
  SourceLocation orientation_where;
};

// A shell element card with N grids: CQUAD4 (4) or CTRIA3 (3).
template <int N>
struct ShellCard {
  int id = 0;
  int property = 0;
  std::array<int, N> grids{};
  SourceLocation where, property_where;
  std::array<SourceLocation, N> grid_where;
};
using QuadCard = ShellCard<4>;
using TriangleCard = ShellCard<3>;

// CONM2 without offset: mass and inertia about the grid in system `system` (-1, 0: basic).
struct MassCard {
  int id = 0;
  int grid = 0;
  int system = 0;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // X1-X3 as given
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // [[I11, -I21, -I31], ...]
  SourceLocation where, grid_where, system_where;
};

// RBE2: the dependent grids GM follow the independent grid GN rigidly in components CM.
struct RigidElementCard {
  int id = 0;
  int independent = 0;     // GN
  std::string components;  // CM, digits 1-6
  std::vector<int> dependent;  // GMi
  SourceLocation where, independent_where;
  std::vector<SourceLocation> dependent_where;
};

// RBE3: the reference grid's components REFC are the weighted average of the groups'.
struct InterpolationElementCard {
  struct Group {
    double weight = 1.0;     // WTi
    std::string components;  // Ci
    std::vector<int> grids;  // Gi,j
    std::vector<SourceLocation> grid_where;
  };
  int id = 0;
  int reference = 0;                 // REFGRID
  std::string reference_components;  // REFC
  std::vector<Group> groups;
  SourceLocation where, reference_where;
};

// One end of a scalar element (CELAS1/2, CMASS1/2): a grid and a component 1-6, or ground
// (grid 0).
struct ScalarEnd {
  int grid = 0;
  int component = 0;
  SourceLocation where;
};

// CELAS1/CELAS2 (stiffness) and CMASS1/CMASS2 (mass): a value between two scalar ends,
// either given (CELAS2, CMASS2) or from a PELAS/PMASS property.
struct ScalarElementCard {
  int id = 0;
  std::string card;               // "CELAS1", "CELAS2", "CMASS1", "CMASS2"
  std::optional<int> property;    // PID of CELAS1 / CMASS1
  double value = 0.0;             // K or M of CELAS2 / CMASS2
  std::array<ScalarEnd, 2> ends;
  SourceLocation where, property_where;
};

// PELAS (K) or PMASS (M): one scalar per property id.
struct ScalarPropertyCard {
  int id = 0;
  std::string card;  // "PELAS", "PMASS"
  double value = 0.0;
  SourceLocation where;
};

// CBUSH between GA and GB (0: grounded) with element axes of the rectangular system CID.
struct BushCard {
  int id = 0;
  int property = 0;
  std::array<int, 2> grids{};  // GB = 0: grounded
  int system = 0;              // CID
  SourceLocation where, property_where, system_where;
  std::array<SourceLocation, 2> grid_where;
};

// PBUSH: stiffnesses K1-K6 along and about the element axes (N/m, N m/rad).
struct BushPropertyCard {
  int id = 0;
  std::array<double, 6> stiffness{};
  SourceLocation where;
};

// CONM1: a 6x6 mass matrix (symmetric, from its lower triangle) at a grid, in system CID.
struct GeneralMassCard {
  int id = 0;
  int grid = 0;
  int system = 0;
  Eigen::Matrix<double, 6, 6> mass = Eigen::Matrix<double, 6, 6>::Zero();
  SourceLocation where, grid_where, system_where;
};

// CROD (-> PROD) or CONROD (material and section on the card): axial and torsional rod.
struct RodCard {
  int id = 0;
  std::string card;  // "CROD", "CONROD"
  int property = 0;  // PROD id (CROD)
  std::array<int, 2> grids{};
  SourceLocation where, property_where;
  std::array<SourceLocation, 2> grid_where;
  // CONROD's own section (CROD: from PROD).
  int material = 0;
  double area = 0.0, torsion_constant = 0.0, nonstructural_mass = 0.0;
  SourceLocation material_where;
};

// PROD: material, A, J, NSM (per length).
struct RodPropertyCard {
  int id = 0;
  int material = 0;
  double area = 0.0, torsion_constant = 0.0, nonstructural_mass = 0.0;
  SourceLocation where, material_where;
};

// Ids from a card: one id (first == last) or an "A THRU B" range. Ranges are kept as such: a
// range holds the grids of the deck within it (it need not be dense), and a large range costs
// nothing.
struct IdRange {
  int first = 0;
  int last = 0;
};

// Grids whose components an SPC or SPC1 card of set `set` holds.
struct SpcEntry {
  int set = 0;
  IdRange grids;
  std::string components;  // digits 1-6
  SourceLocation where;
};

// Cards that were read but that limber does not use: by name, with a count and their lines.
struct CardTally {
  int count = 0;
  std::vector<SourceLocation> first;  // the first few places
};

struct Deck {
  std::string file;  // the main deck file
  std::map<int, CoordinateSystemCard> coordinate_systems;
  std::map<int, GridCard> grids;
  std::map<int, MaterialCard> materials;
  std::map<int, BeamPropertyCard> beam_properties;
  std::map<int, ShellPropertyCard> shell_properties;
  std::map<int, BeamCard> beams;
  std::map<int, QuadCard> quads;
  std::map<int, TriangleCard> triangles;
  std::map<int, MassCard> masses;
  std::map<int, RigidElementCard> rigid_elements;                // RBE2
  std::map<int, InterpolationElementCard> interpolation_elements;  // RBE3
  std::map<int, ScalarElementCard> scalar_elements;  // CELAS1/2, CMASS1/2
  std::map<int, ScalarPropertyCard> scalar_properties;  // PELAS, PMASS
  std::map<int, BushCard> bushes;
  std::map<int, BushPropertyCard> bush_properties;
  std::map<int, GeneralMassCard> general_masses;  // CONM1
  std::map<int, RodCard> rods;                    // CROD, CONROD
  std::map<int, RodPropertyCard> rod_properties;  // PROD
  std::vector<std::string> parse_notices;  // e.g. PBUSH damping left out
  std::vector<SpcEntry> spcs;
  std::map<int, std::vector<IdRange>> spc_sets_added;  // SPCADD: set -> sets
  std::map<int, std::vector<IdRange>> sets;            // SET1: id -> members
  double mass_factor = 1.0;                        // PARAM,WTMASS
  // Cards without effect on the structure's stiffness and mass (loads, solution requests,
  // output, parameters other than WTMASS).
  std::map<std::string, CardTally> ignored;
  // Cards that would change the structure and that limber does not read.
  std::map<std::string, CardTally> unsupported;
};

}  // namespace limber::bulkdata
