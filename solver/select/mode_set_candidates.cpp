#include "select/mode_set_candidates.h"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "core/error.h"

namespace limber::select {

namespace {

const io::FlexibleBodyCase& component_of(const io::Case& input, const std::string& name) {
  for (const io::FlexibleBodyCase& body : input.flexible_bodies) {
    if (body.name == name) return body;
  }
  throw InputError("expected an entry of 'flexible_bodies' named '" + name + "', got none");
}

// The `flexible_bodies` entry of a ranked component's body.
const std::string& component_name(const io::Case& input, const RankedComponent& component) {
  return input.mechanism->flexible_components.at(component.body);
}

fe::Dof component_dof(const RankedComponent& component) {
  return static_cast<fe::Dof>(component.column());
}

bool is_fixed(const fe::FeModel& model, int node, fe::Dof dof) {
  return std::any_of(model.fixed_dofs.begin(), model.fixed_dofs.end(),
                     [&](const fe::FixedDof& f) { return f.node == node && f.dof == dof; });
}

// Adds a static mode at (node, dof) to the request's sites of `kind`; false when it was there.
bool add_static_mode(modal::ModeRequest& request, StaticModeKind kind, int node, fe::Dof dof) {
  std::vector<modal::StaticModeSite>& sites =
      kind == StaticModeKind::kAttachment ? request.attachment_sites : request.constraint_sites;
  auto site = std::find_if(sites.begin(), sites.end(),
                           [&](const modal::StaticModeSite& s) { return s.node == node; });
  if (site == sites.end()) {
    sites.push_back({node, {dof}});
    return true;
  }
  if (std::find(site->dofs.begin(), site->dofs.end(), dof) != site->dofs.end()) return false;
  site->dofs.push_back(dof);
  return true;
}

int static_mode_count(const modal::ModeRequest& request) {
  int count = 0;
  for (const auto* sites : {&request.attachment_sites, &request.constraint_sites}) {
    for (const modal::StaticModeSite& site : *sites) count += static_cast<int>(site.dofs.size());
  }
  return count;
}

// The normal modes the normal-mode run computed for a body.
int normal_count(const io::FlexibleBodyCase& body, const io::CaseReduction& normal) {
  const io::BodyReduction* reduced = normal.find(body.name);
  return reduced ? static_cast<int>(reduced->result.mode_set.shapes.cols()) : body.request.normal_count;
}

// Every body's request with `normal` normal modes (by count) and its static modes kept.
io::ModeOverrides with_normal_counts(io::ModeOverrides requests,
                                     const std::map<std::string, int>& counts) {
  for (auto& [name, request] : requests) {
    request.normal_count = counts.at(name);
    request.max_frequency_hz.reset();
  }
  return requests;
}

// Text of a mode request, to tell equal sets apart.
std::string request_key(const io::ModeOverrides& requests) {
  std::string key;
  for (const auto& [name, request] : requests) {
    key += name + ":" + modes_yaml(request, {}) + ";";
  }
  return key;
}

}  // namespace

io::ModeOverrides normal_only(const io::Case& input) {
  io::ModeOverrides requests;
  for (const auto& [body, component] : input.mechanism->flexible_components) {
    const io::FlexibleBodyCase& entry = component_of(input, component);
    if (entry.request.normal_count == 0 && !entry.request.max_frequency_hz) {
      throw InputError("expected normal modes for flexible body '" + component +
                           "' ('normal' under 'modes'): the selection starts from a normal-mode run",
                       entry.modes_where);
    }
    modal::ModeRequest request = entry.request;
    request.attachment_sites.clear();
    request.constraint_sites.clear();
    requests[component] = request;
  }
  return requests;
}

std::vector<ModeSetCandidate> mode_set_candidates(const io::Case& input, const io::CaseReduction& normal_run,
                                                  const std::vector<RankedComponent>& ranking,
                                                  const CandidateOptions& options) {
  const io::ModeOverrides normal = normal_only(input);
  const char* kind = options.static_kind == StaticModeKind::kAttachment ? "attachment" : "constraint";
  std::vector<ModeSetCandidate> candidates;
  candidates.push_back({"normal", "normal modes only", normal, false});

  // One component at a time, then all kept together.
  ModeSetCandidate kept{"kept", "", normal, false};
  std::vector<std::string> kept_labels;
  std::vector<std::string> seen_keys = {request_key(normal)};
  int singles = 0;
  const int max_single = options.max_single.value_or(kMaxSingle);
  for (const RankedComponent& component : ranking) {
    if (!component.kept) continue;
    const std::string& name = component_name(input, component);
    const io::FlexibleBodyCase& entry = component_of(input, name);
    const fe::Dof dof = component_dof(component);
    if (is_fixed(entry.model, component.site.node, dof)) continue;
    if (!add_static_mode(kept.requests[name], options.static_kind, component.site.node, dof)) continue;
    kept_labels.push_back(component.label());
    if (singles >= max_single) continue;
    ModeSetCandidate single{"normal+" + component.label(),
                            fmt::format("normal modes + the {} mode of {} at node {}", kind,
                                        component.label(), component.node_id),
                            normal, false};
    add_static_mode(single.requests[name], options.static_kind, component.site.node, dof);
    // Bodies sharing one mode set can make two components the same static mode.
    const std::string key = request_key(single.requests);
    if (std::find(seen_keys.begin(), seen_keys.end(), key) != seen_keys.end()) continue;
    seen_keys.push_back(key);
    candidates.push_back(std::move(single));
    ++singles;
  }
  if (kept_labels.empty()) {
    throw InputError("expected at least one kept reaction component on a free DOF of a flexible "
                     "body, got none (lower --keep?)");
  }
  std::string labels;
  for (const std::string& label : kept_labels) labels += (labels.empty() ? "" : ", ") + label;
  kept.description = fmt::format("normal modes + {} modes of every kept component ({})", kind, labels);
  candidates.push_back(kept);

  // Like for like: the same number of modes, all normal; then the richest set.
  std::map<std::string, int> more, reference;
  for (const auto& [name, request] : kept.requests) {
    const int normals = normal_count(component_of(input, name), normal_run);
    more[name] = normals + static_mode_count(request);
    reference[name] = options.reference_normal > 0 ? options.reference_normal : 4 * normals;
  }
  io::ModeOverrides more_requests = with_normal_counts(normal, more);
  candidates.push_back({"more_normal", "as many modes as 'kept', all of them normal modes",
                        more_requests, false});
  std::string reference_counts;
  for (const auto& [name, count] : reference) {
    reference_counts += fmt::format("{}{} {}", reference_counts.empty() ? "" : ", ", count, name);
  }
  candidates.push_back({"reference",
                        fmt::format("{} normal modes + the kept {} modes: the richest set",
                                    reference_counts, kind),
                        with_normal_counts(kept.requests, reference), true});
  return candidates;
}

std::string modes_yaml(const modal::ModeRequest& request, const std::vector<int>& node_ids) {
  const auto id = [&](int node) {
    return node_ids.empty() ? node : node_ids[static_cast<std::size_t>(node)];
  };
  std::string text;
  if (request.max_frequency_hz) {
    text = fmt::format("normal: {{count: {}, max_frequency_hz: {:g}}}\n", request.normal_count,
                       *request.max_frequency_hz);
  } else {
    text = fmt::format("normal: {}\n", request.normal_count);
  }
  const auto sites_yaml = [&](const char* key, const std::vector<modal::StaticModeSite>& sites) {
    if (sites.empty()) return;
    text += std::string(key) + ": [";
    for (std::size_t s = 0; s < sites.size(); ++s) {
      std::string dofs;
      for (fe::Dof dof : sites[s].dofs) {
        dofs += (dofs.empty() ? "" : ", ") + std::string(fe::dof_name(dof));
      }
      text += fmt::format("{}{{nodes: [{}], dofs: [{}]}}", s ? ", " : "", id(sites[s].node), dofs);
    }
    text += "]\n";
  };
  sites_yaml("constraint", request.constraint_sites);
  sites_yaml("attachment", request.attachment_sites);
  if (request.dependency_tolerance != modal::ModeRequest{}.dependency_tolerance) {
    text += fmt::format("dependency_tolerance: {:g}\n", request.dependency_tolerance);
  }
  return text;
}

}  // namespace limber::select
