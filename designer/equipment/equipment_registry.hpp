#pragma once
// One row per equipment kind: how the designer checks it on the reduced rungs, how the
// estimates of every rung are judged against the case's targets, which scene verifies it on
// each full rung, and which full rung the seed's rule picks and why. Adding an equipment is its
// check, judge and scene adapters plus one row here; nothing else dispatches on the kind.
#include <memory>
#include <span>

#include "designer/case/case.hpp"
#include "designer/design/design_detail.hpp"
#include "designer/design/model_choices.hpp"
#include "designer/simulate/scene_adapter.hpp"

namespace feedflow {

struct EquipmentEntry {
  EquipmentKind kind;
  // The design check (rungs L0 and L1): evaluate the reduced models, judge, explain.
  void (*check)(const Case&, const ModelChoices&, DesignDetail, DesignRecord&);
  // The judge of every rung: the case's targets and any rung's estimates to a verdict.
  Verdict (*judge)(const Case&, const Estimates&);
  // The scene that verifies the case on each full rung.
  std::unique_ptr<SceneAdapter> (*dem)(const SimulationRequest&);
  std::unique_ptr<SceneAdapter> (*cel)(const SimulationRequest&);
  Solver default_solver;  // the seed's rule (section 4) ...
  const char* why;        // ... and why, for the log and the record's assumptions
};

std::span<const EquipmentEntry> equipment_registry();
const EquipmentEntry& equipment_of(EquipmentKind kind);

}  // namespace feedflow
