// The tokenizer (card_reader.h) and field rules (card_fields.h): formats, continuations,
// comments, INCLUDE, executive/case control, NASTRAN number forms.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "bulkdata/card_fields.h"
#include "bulkdata/card_reader.h"
#include "bulkdata/deck_parser.h"
#include "deck_text.h"

namespace limber::bulkdata {
namespace {

using test::card_text;
using test::FieldFormat;

// Field texts of a card, blanks included, up to its last non-blank field.
std::vector<std::string> data(const Card& card) {
  std::vector<std::string> texts;
  for (const Field& field : card.fields) texts.push_back(field.text);
  while (!texts.empty() && texts.back().empty()) texts.pop_back();
  return texts;
}

TEST(NastranNumbers, RealFormsOfTheQuickReferenceGuide) {
  // Every form NASTRAN accepts for 7.0 x 10^10 and friends.
  EXPECT_EQ(parse_real("7.0E10"), 7.0e10);
  EXPECT_EQ(parse_real("7.E+10"), 7.0e10);
  EXPECT_EQ(parse_real("7.+10"), 7.0e10);
  EXPECT_EQ(parse_real("70.D9"), 7.0e10);
  EXPECT_EQ(parse_real(".7E11"), 7.0e10);
  EXPECT_EQ(parse_real("-1.5-3"), -1.5e-3);
  EXPECT_EQ(parse_real("+.5"), 0.5);
  EXPECT_EQ(parse_real("0."), 0.0);
  // Not reals: no decimal point, a bad exponent, embedded text.
  EXPECT_FALSE(parse_real("7"));
  EXPECT_FALSE(parse_real("7E10"));
  EXPECT_FALSE(parse_real("7.E"));
  EXPECT_FALSE(parse_real("7.0E1X"));
  EXPECT_FALSE(parse_real("1.0.0"));
  EXPECT_FALSE(parse_real("."));
  EXPECT_FALSE(parse_real("1.+400"));  // overflows
  EXPECT_EQ(parse_integer("12"), 12);
  EXPECT_EQ(parse_integer("-1"), -1);
  EXPECT_FALSE(parse_integer("1."));
  EXPECT_FALSE(parse_integer("99999999999"));
}

TEST(CardReader, SmallLargeAndFreeFieldGiveTheSameFields) {
  // A CORD2R (two lines of data) and a GRID with every field.
  const std::vector<std::string> cord = {"CORD2R", "3", "0", "1.5", "2.", "-3.", "1.5",
                                         "2.", "4.25", "2.5", "2.", "-3."};
  const std::vector<std::string> grid = {"GRID", "17", "3", "1.25", ".5", "-2.+1", "0", "456"};
  std::vector<std::vector<std::string>> parsed;
  for (FieldFormat format : {FieldFormat::kSmall, FieldFormat::kLarge, FieldFormat::kFree}) {
    const std::string text = card_text(format, cord) + card_text(format, grid);
    const std::vector<Card> cards = read_cards_text(text, "deck.bdf");
    ASSERT_EQ(cards.size(), 2u) << text;
    EXPECT_EQ(cards[0].name, "CORD2R");
    EXPECT_EQ(cards[1].name, "GRID");
    std::vector<std::string> all = data(cards[0]);
    // The continuation starts NASTRAN field 12: the first line's 8 data fields, padded.
    ASSERT_GE(all.size(), 11u) << text;
    EXPECT_EQ(all[8], "2.5") << text;
    for (const std::string& t : data(cards[1])) all.push_back(t);
    parsed.push_back(all);
  }
  EXPECT_EQ(parsed[0], parsed[1]);
  EXPECT_EQ(parsed[0], parsed[2]);

  // And the parsed deck agrees with the fields as written.
  const Deck deck = parse_deck(read_cards_text(card_text(FieldFormat::kLarge, cord) +
                                                   card_text(FieldFormat::kSmall, grid),
                                               "deck.bdf"),
                               "deck.bdf");
  const GridCard& g = deck.grids.at(17);
  EXPECT_EQ(g.position_system, 3);
  EXPECT_EQ(g.position, Eigen::Vector3d(1.25, 0.5, -20.0));
  EXPECT_EQ(g.permanent_spc, "456");
  EXPECT_EQ(deck.coordinate_systems.at(3).c, Eigen::Vector3d(2.5, 2.0, -3.0));
}

TEST(CardReader, ContinuationsCommentsTabsAndCase) {
  // Explicit (+, *) and implicit (blank field 1) continuations, a comment line, a trailing
  // comment, a tab, lower case.
  const std::string text =
      "$ a comment line\n"
      "cord2r  1       0       0.      0.      0.      0.      0.      1.      +C1\n"
      "+C1     1.      0.      0.\n"
      "GRID*   5               0               1.0             2.0             *G5\n"
      "*G5     3.0\n"
      "GRID    6       \t1.0     2.0     3.0 $ trailing comment\n"
      "CORD2R  2       0       0.      0.      0.      0.      0.      1.\n"
      "        1.      0.      0.\n";
  const std::vector<Card> cards = read_cards_text(text, "deck.bdf");
  ASSERT_EQ(cards.size(), 4u);
  EXPECT_EQ(cards[0].name, "CORD2R");
  EXPECT_EQ(data(cards[0])[8], "1.");
  EXPECT_EQ(data(cards[1]), (std::vector<std::string>{"5", "0", "1.0", "2.0", "3.0"}));
  // The tab at column 17 moves "1.0" to the next tab stop, column 25: field 4 (X1).
  EXPECT_EQ(data(cards[2]), (std::vector<std::string>{"6", "", "1.0", "2.0", "3.0"}));
  EXPECT_EQ(cards[2].fields[2].column, 25);
  EXPECT_EQ(data(cards[3])[8], "1.");
  EXPECT_EQ(cards[3].line, 7);
}

TEST(CardReader, SkipsExecutiveAndCaseControlAndStopsAtEnddata) {
  const std::string text =
      "SOL 103\nCEND\nTITLE = X\nSUBCASE 1\n  SPC = 1\nBEGIN BULK\n"
      "GRID,1,,0.,0.,0.\nENDDATA\nGRID,2,,0.,0.,0.\n";
  const std::vector<Card> cards = read_cards_text(text, "deck.bdf");
  ASSERT_EQ(cards.size(), 1u);
  EXPECT_EQ(cards[0].line, 7);
  // Case control without BEGIN BULK is not a bulk-data deck.
  try {
    read_cards_text("SOL 103\nCEND\nGRID,1,,0.,0.,0.\n", "deck.bdf");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 2) << error.what();
    EXPECT_NE(std::string(error.what()).find("BEGIN BULK"), std::string::npos);
  }
}

TEST(CardReader, ContinuationMarkersPairCardsAcrossTheDeck) {
  // PBEAM 7's continuation (marker +P7 in columns 73-80) comes after another card, in small
  // field; GRID 2's free-field continuation (*G2 matches +G2) comes last; the CONM2 line's
  // continuation, with an unmatched marker, continues the card above as before.
  std::string text = fmt::format("{:<8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:<8}\n", "PBEAM", "7", "1", "1.",
                                 "2.", "3.", "", "4.", "", "+P7");
  text += "GRID,1,,0.,0.,0.\n";
  text += "GRID,2,,1.,2.,3.,,,,+G2\n";
  text += fmt::format("{:<8}{:>8}{:>8}\n", "+P7", "YES", "1.");
  text += "CONM2,9,1,,2.,,,,,+X\n+Y,1.,,1.,,,1.\n";
  text += "*G2,0\n";
  const std::vector<Card> cards = read_cards_text(text, "deck.bdf");
  ASSERT_EQ(cards.size(), 4u);
  EXPECT_EQ(cards[0].name, "PBEAM");
  ASSERT_EQ(cards[0].fields.size(), 16u);
  EXPECT_EQ(cards[0].fields[8].text, "YES");
  EXPECT_EQ(cards[0].fields[8].line, 4);
  EXPECT_EQ(cards[2].name, "GRID");
  ASSERT_EQ(cards[2].fields.size(), 12u);  // 8 small fields, then 4 large ones ('*')
  EXPECT_EQ(cards[2].fields[8].text, "0");
  EXPECT_EQ(cards[3].fields.size(), 16u);
  // A continuation with no card before it and no matching marker.
  try {
    read_cards_text("+Q1,1.\nGRID,1,,0.,0.,0.,,,,+Q1\n", "deck.bdf");
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 1) << error.what();
  }
}

TEST(CardReader, ErrorsNameLineAndColumn) {
  // A continuation with nothing before it, a bad name, too many free fields.
  const auto fails = [](const std::string& text, const std::string& where,
                        const std::string& words) {
    try {
      read_cards_text(text, "deck.bdf");
    } catch (const InputError& error) {
      EXPECT_EQ(error.where().to_string(), where) << error.what();
      EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
      return;
    }
    ADD_FAILURE() << "expected an InputError for " << text;
  };
  fails("+       1.\n", "deck.bdf:1:1", "continuation line with no card");
  fails("GRID,1\n1GRID,2\n", "deck.bdf:2:1", "expected a card name");
  fails("GRID,1,,0.,0.,0.,,,,,X\n", "deck.bdf:1:22", "at most 10 fields");
  fails("INCLUDE 'missing.bdf\n", "deck.bdf:1:1", "closing quote");
}

// A file with `text` at `path` (folders made).
void write_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

TEST(CardReader, IncludeRelativePathsAndCycles) {
  const std::filesystem::path root =
      std::filesystem::temp_directory_path() / ("limber_include_" + std::to_string(::getpid()));
  std::filesystem::remove_all(root);
  // main includes sub/part.bdf, which includes ../more.bdf (relative to sub/).
  write_file(root / "main.bdf",
             "SOL 103\nCEND\nBEGIN BULK\nGRID,1,,0.,0.,0.\nINCLUDE 'sub/part.bdf'\n"
             "GRID,4,,0.,0.,0.\nENDDATA\n");
  write_file(root / "sub" / "part.bdf", "GRID,2,,0.,0.,0.\ninclude ../more.bdf\n");
  write_file(root / "more.bdf", "GRID,3,,0.,0.,0.\n");
  const std::vector<Card> cards = read_cards((root / "main.bdf").string());
  ASSERT_EQ(cards.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(cards[k].fields[0].text, std::to_string(k + 1));
  EXPECT_EQ(*cards[1].file, (root / "main.bdf").parent_path() / "sub/part.bdf");

  // a.bdf -> b.bdf -> a.bdf: an error at b's INCLUDE that shows the chain.
  write_file(root / "a.bdf", "GRID,1,,0.,0.,0.\nINCLUDE 'b.bdf'\n");
  write_file(root / "b.bdf", "\nINCLUDE 'a.bdf'\n");
  try {
    read_cards((root / "a.bdf").string());
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 2) << error.what();
    EXPECT_NE(error.where().file.find("b.bdf"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("cycle"), std::string::npos) << error.what();
  }
  // A missing include names the INCLUDE line.
  write_file(root / "c.bdf", "GRID,1,,0.,0.,0.\nINCLUDE 'nowhere.bdf'\n");
  try {
    read_cards((root / "c.bdf").string());
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 2) << error.what();
    EXPECT_NE(std::string(error.what()).find("nowhere.bdf"), std::string::npos) << error.what();
  }
  std::filesystem::remove_all(root);
}

}  // namespace
}  // namespace limber::bulkdata
