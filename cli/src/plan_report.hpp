#pragma once
// What `ncbridge plan` writes beside the CC2 file: the report (the same `features` array as
// `convert --report --level cc2`, docs/formats/report.md, plus the part's own sections:
// docs/plan.md) and the HTML page (the features seen from above, html_report.hpp).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cc2_output.hpp"
#include "ncbridge/part_reader/part.hpp"
#include "ncbridge/process_planner/planner.hpp"
#include "ncbridge/setup/stock.hpp"

namespace ncbridge::cli {

// The plan in the shape the CC2 report and page take: each planned feature as a recognised
// feature (centre, z, dimensions, bottom, open sides, slot ends) with its planned operations.
Cc2Output plan_as_cc2(const part_reader::Part& part, const process_planner::Plan& plan, const setup::Stock& stock);

// The part's sections of the report: features not planned (their axis and the setup they need),
// compounds (counterbores, countersinks), listed features with their parameters.
nlohmann::ordered_json part_sections(const part_reader::Part& part, const process_planner::Plan& plan);

}  // namespace ncbridge::cli
