#include "deck_input_path.h"

#include <algorithm>

#include "bulkdata/deck_parser.h"
#include "bulkdata/deck_to_fe.h"
#include "fe/assembly.h"
#include "modal/component_modes.h"

namespace limber::fuzz {

const char* to_string(DeckOutcome outcome) {
  switch (outcome) {
    case DeckOutcome::kAccepted: return "accepted";
    case DeckOutcome::kInputError: return "input error";
    case DeckOutcome::kNoModes: return "no modes";
  }
  return "?";
}

DeckOutcome run_deck_input(const std::string& text, const std::string& file, int max_nodes,
                           std::string* message) {
  try {
    // Read and translate; unsupported cards become notices so that the rest is reached.
    const bulkdata::Deck deck = bulkdata::parse_deck(bulkdata::read_cards_text(text, file), file);
    bulkdata::DeckOptions options;
    options.unsupported_is_error = false;
    if (!deck.spcs.empty()) options.spc_set = deck.spcs.front().set;
    fe::FeModelBuilder builder;
    bulkdata::add_deck(deck, options, builder);
    const fe::FeModel model = std::move(builder).build();
    if (model.node_count() > max_nodes) return DeckOutcome::kAccepted;

    // Element matrices (a warped quad is an InputError) and a few normal modes.
    const fe::StructuralMatrices matrices = fe::assemble(model);
    modal::ModeRequest request;
    request.normal_count =
        std::min(4, model.dof_count() - static_cast<int>(model.fixed_dofs.size()) - 6);
    if (request.normal_count < 1) return DeckOutcome::kAccepted;
    const modal::ModalResult result = modal::compute_component_modes(model, matrices, request);
    if (result.status != modal::ModalStatus::kOk) {
      if (message) *message = result.message;
      return DeckOutcome::kNoModes;
    }
    return DeckOutcome::kAccepted;
  } catch (const InputError& error) {
    if (message) *message = error.what();
    return DeckOutcome::kInputError;
  }
}

}  // namespace limber::fuzz
