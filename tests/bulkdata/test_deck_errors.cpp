// Bad decks: each error names the file, line and column of the offending field and says what
// was expected (house style §11). Also the MAT1 rule and the unsupported-card policy.
#include <gtest/gtest.h>

#include <cmath>

#include "bulkdata/deck_parser.h"
#include "bulkdata/deck_to_fe.h"
#include "deck_text.h"
#include "fe/fe_model_builder.h"

namespace limber::bulkdata {
namespace {

using test::deck_location;

// A valid plate strip: two quads on grids 1-6, PSHELL 1, MAT1 1.
const std::string kPlate =
    "MAT1,1,7.+10,,0.3,2700.\n"
    "PSHELL,1,1,.002,1,,1\n"
    "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,2.,0.,0.\n"
    "GRID,4,,0.,1.,0.\nGRID,5,,1.,1.,0.\nGRID,6,,2.,1.,0.\n"
    "CQUAD4,10,1,1,2,5,4\nCQUAD4,11,1,2,3,6,5\n";

std::vector<std::string> translate(const std::string& text, const DeckOptions& options = {}) {
  const Deck deck = parse_deck(read_cards_text(text, "deck.bdf"), "deck.bdf");
  fe::FeModelBuilder builder;
  return add_deck(deck, options, builder);
}

// Fails at the place of `marker` (its `occurrence`-th appearance) with `words`.
::testing::AssertionResult fails_at(const std::string& text, const std::string& where,
                                    const std::string& words, const DeckOptions& options = {}) {
  try {
    translate(text, options);
  } catch (const InputError& error) {
    const std::string got = error.what();
    if (got.rfind(where + ": ", 0) != 0) {
      return ::testing::AssertionFailure() << "expected the location " << where << ", got: " << got;
    }
    if (got.find(words) == std::string::npos) {
      return ::testing::AssertionFailure() << "expected '" << words << "', got: " << got;
    }
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "expected an InputError, got none";
}

TEST(DeckErrors, TheValidPlateTranslates) { EXPECT_NO_THROW(translate(kPlate)); }

TEST(DeckErrors, BadFields) {
  // A real that is not one, a real without a decimal point, an integer that is a real.
  std::string text = kPlate + "GRID,7,,1.0.0,0.,0.\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "1.0.0"), "GRID 7, field 4 (X1): expected a real"));
  text = "MAT1,1,70000000000,,0.3,2700.\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "70000000000"), "with a decimal point"));
  text = "GRID,1.5,,0.,0.,0.\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "1.5"), "field 2 (ID): expected an integer"));
  // In small-field format the column is the field's own.
  text = "GRID           1       0     abc      0.      0.\n";
  EXPECT_TRUE(fails_at(text, "deck.bdf:1:30", "field 4 (X1)"));
  // Components outside 1-6.
  text = kPlate + "SPC1,1,1237,1\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "1237"), "component digits 1-6"));
  // Features limber does not model, at their fields.
  text = kPlate + "CQUAD4,12,1,1,2,5,4,,0.001\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "0.001"), "ZOFFS"));
  text = "PBAR,1,1,1.-4,2.-9,1.-9,3.-9,0.5\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "0.5"), "non-structural mass on beams"));
}

TEST(DeckErrors, MissingPropertyMaterialGridAndWrongKind) {
  std::string text = kPlate + "CQUAD4,12,9,1,2,5,4\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "9,1,2,5,4"),
                       "CQUAD4 12, field 3 (PID): expected a defined PSHELL id, got 9"));
  text = "MAT1,1,7.+10,,0.3,2700.\nPSHELL,1,7,.002,7\n" + kPlate.substr(kPlate.find("GRID"));
  EXPECT_TRUE(fails_at(text, deck_location(text, "7,.002"),
                       "PSHELL 1, field 3 (MID1): expected a defined MAT1 id, got 7"));
  text = kPlate + "CQUAD4,12,1,1,2,5,99\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "99"), "field 7 (G4): expected a defined GRID id"));
  // A CBAR on a PSHELL.
  text = kPlate + "CBAR,12,1,1,2,0.,0.,1.\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "1,1,2,0."), "expected a defined PBAR or PBARL id"));
}

TEST(DeckErrors, DuplicateIds) {
  std::string text = kPlate + "GRID,3,,5.,0.,0.\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "3,,5."), "expected a unique GRID id, got 3 again "
                                                         "(first at deck.bdf:5:1)"));
  // Element ids are shared by all elements, CONM2 included.
  text = kPlate + "CONM2,11,1,,2.\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "11,1,,2."), "expected a unique element id"));
  // Property ids are shared by PBAR and PSHELL.
  text = kPlate + "PBAR,1,1,1.-4,2.-9,1.-9,3.-9\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "1,1,1.-4"), "expected a unique property id"));
}

TEST(DeckErrors, Mat1TakesTwoOfEGNu) {
  const auto material = [](const std::string& card) {
    return parse_deck(read_cards_text(card, "deck.bdf"), "deck.bdf").materials.at(1).material;
  };
  // E and G: nu = E / (2 G) - 1; G and nu: E = 2 (1 + nu) G.
  EXPECT_NEAR(material("MAT1,1,7.+10,2.6+10\n").poisson_ratio, 7.0 / 5.2 - 1.0, 1e-15);
  // (Tolerances: a few roundings of the products.)
  EXPECT_NEAR(material("MAT1,1,,2.6+10,0.3\n").youngs_modulus, 6.76e10, 6.76e10 * 1e-14);
  // All three, consistent within 1 % (G rounded): E and nu kept.
  EXPECT_EQ(material("MAT1,1,7.+10,2.69+10,0.3\n").youngs_modulus, 7.0e10);
  std::string text = "MAT1,1,7.+10,3.0+10,0.3\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "3.0+10"), "G = E / (2 (1 + NU))"));
  text = "MAT1,1,7.+10\n";
  EXPECT_TRUE(fails_at(text, "deck.bdf:1:1", "expected two of E (field 3), G (field 4) and NU"));
}

TEST(DeckErrors, UnsupportedCardsAreErrorsUnlessAllowed) {
  const std::string text = kPlate + "CTRIA6,20,1,1,2,5\nRBAR,30,1,2,123456\nCTRIA6,21,1,2,3,6\n"
                                    "FORCE,1,5,,1.,0.,0.,1.\n";
  DeckOptions options;
  options.where = {"case.yaml", 4, 16};
  // The error is at the case entry and lists each card with its count and lines.
  EXPECT_TRUE(fails_at(text, "case.yaml:4:16",
                       "CTRIA6 (2 cards: deck.bdf:11, deck.bdf:13); RBAR (1 card: deck.bdf:12)",
                       options));
  // Allowed: a notice with the same list; FORCE (a load) is ignored either way.
  options.unsupported_is_error = false;
  const std::vector<std::string> notices = translate(text, options);
  ASSERT_EQ(notices.size(), 2u);
  EXPECT_NE(notices[0].find("CTRIA6 (2 cards"), std::string::npos) << notices[0];
  EXPECT_NE(notices[1].find("FORCE (1 card: deck.bdf:14)"), std::string::npos) << notices[1];
}

TEST(DeckSets, ThruRangesHoldTheGridsWithinThem) {
  // Grids 1-6 exist; 1 THRU 1000000 holds those six (no expansion of the range), a single id
  // must be a grid.
  std::string text = kPlate + "SPC1,1,345,1,THRU,1000000\nSPC,2,4,12\nSPCADD,3,1,2\nSET1,10,2,THRU,5\n";
  DeckOptions options;
  options.spc_set = 3;
  const Deck deck = parse_deck(read_cards_text(text, "deck.bdf"), "deck.bdf");
  fe::FeModelBuilder builder;
  add_deck(deck, options, builder);
  // 6 grids x 3 components from set 1, plus components 1 and 2 of grid 4 from set 2.
  EXPECT_EQ(builder.peek().fixed_dofs.size(), 6u * 3u + 2u);
  EXPECT_EQ(builder.peek().node_sets.at("set10").size(), 4u);
  text = kPlate + "SPC1,1,3,77\n";
  options.spc_set = 1;
  EXPECT_TRUE(fails_at(text, deck_location(text, "SPC1"), "expected a defined GRID id, got 77", options));
}

TEST(DeckSets, CaseControlSetLinesAreNodeSets) {
  // SET 20 over two lines (a trailing comma continues), a set of ALL (no list: skipped), and
  // a set whose id clashes with a SET1 (an error at the second).
  std::string text = "SOL 103\nCEND\nSET 20 = 1, 3 THRU 5,\n   6\nSET 21 = ALL\nDISP = 20\nBEGIN BULK\n" + kPlate;
  fe::FeModelBuilder builder;
  add_deck(parse_deck(read_cards_text(text, "deck.bdf"), "deck.bdf"), {}, builder);
  EXPECT_EQ(builder.peek().node_sets.at("set20"), (std::vector<int>{0, 2, 3, 4, 5}));
  EXPECT_FALSE(builder.peek().node_sets.contains("set21"));
  text = "SOL 103\nCEND\nSET 10 = 1, 2\nBEGIN BULK\n" + kPlate + "SET1,10,3,4\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "10,3,4"), "expected a unique set id"));
}

TEST(DeckErrors, MassOffsetsAndRotatedConstraints) {
  // A CONM2 off its grid (offset, or CID = -1 at another point) is not a point mass.
  std::string text = kPlate + "CONM2,20,5,,2.,0.1\n";
  EXPECT_TRUE(fails_at(text, deck_location(text, "CONM2"), "mass offsets are not supported"));
  text = kPlate + "CONM2,20,5,-1,2.,1.,1.,0.\n";
  EXPECT_NO_THROW(translate(text));
  // A constraint on part of the translations of a grid in a rotated CD system.
  text = "CORD2R,5,,0.,0.,0.,0.,0.,1.\n,1.,1.,0.\n" + kPlate +
         "GRID,7,,3.,0.,0.,5\nGRID,8,,3.,1.,0.\nCQUAD4,12,1,3,7,8,6\nSPC1,1,12,7\nSPC1,2,123,7\n";
  DeckOptions options;
  options.spc_set = 1;
  EXPECT_TRUE(fails_at(text, deck_location(text, "SPC1,1"), "components 123 and/or 456 as a whole", options));
  options.spc_set = 2;
  EXPECT_NO_THROW(translate(text, options));
  // An SPC set the deck does not define: at the case's place, listing those it does.
  options.spc_set = 3;
  options.spc_where = {"case.yaml", 9, 5};
  EXPECT_TRUE(fails_at(text, "case.yaml:9:5", "got 3; the deck defines 1, 2", options));
}

}  // namespace
}  // namespace limber::bulkdata
