#pragma once
// replay of a tradeoff record, the parts issue 34 adds: whether the budget's
// pick moved (a record with --budget-ms/--budget), and a --search record
// walked again from the same start (BudgetSearch), whether it found the same
// settings. docs/records.md says what each line means.
#include <optional>
#include <string>

#include "app/ReplayReport.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/study/BudgetSearch.h"

namespace dw::replay {

// "pick: the same: point N (...)" or "pick: moved: point A -> point B" (or
// to / from none fitting), from the rows' pick column; nothing when neither
// table has a pick. Returns whether it moved.
bool reportPick(const TradeoffTable& before, const TradeoffTable& after);

// The record's search run again (its start, budget, bound and seeds); prints
// "search: the same: ..." or "search: moved: ..." knob by knob with the
// errors' intervals, then every evaluation both walks measured with the same
// settings old against new (errors, counters, times, front: "tradeoff: the
// same/differs"), and writes `newRecord` when given. `moved` says whether the
// found settings or any such evaluation's numbers differ. Needs a current GL 4.5 context.
BudgetSearchResult replaySearch(const ExperimentRecord& old, const std::string& path, const RecordedTradeoff& again,
                                const std::optional<std::string>& newRecord, const BenchFields& machine, bool& moved);

}  // namespace dw::replay
