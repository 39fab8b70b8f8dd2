#pragma once
// JSON views of results (nlohmann::json). Non-finite numbers become null with a note beside them.
#include <complex>
#include <nlohmann/json.hpp>

#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/model/parameters.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

nlohmann::json to_json(const Parameters& p);  // the parameter table's material rows: inputs, then Lambda, S, alpha
nlohmann::json to_json(const Scene& s);
// The run's keys, then "terminated_at" (null with "terminated_at_reason" when the run was integrated to T) and
// "early_termination" (to_json(EarlyTermination)).
nlohmann::json to_json(const SimulationResult& r);
// to_json(r) with every null explained (explain_nulls): by run_reason when the run stopped, else by the inputs
// that overflowed (nonfinite_reason).
nlohmann::json to_json(const SimulationResult& r, const Parameters& p);
// attempts and rhs_evaluations of the certification, then the certificate (terminated_at, resumed_at, kind,
// period, margin, margin_error, rate, residual, distance, decay_bound) or the note saying why there is none.
nlohmann::json to_json(const EarlyTermination& e);
// {"2": v[0], "3": v[1], ...}
nlohmann::json by_mode(const std::vector<double>& values_from_l2);
// Why a benchmark row's number is not finite: its run's status and message when it stopped, else the inputs that
// overflowed (nonfinite_reason).
std::string row_reason(IntegrationStatus status, const std::string& reason, const Parameters& p);
// "L" and "L_reason" (why that L: SceneFile::L_reason), which every JSON output of a scene carries, and
// "truncation_check" when the file holds one.
void put_truncation(nlohmann::json& j, const SceneFile& file);
nlohmann::json to_json(const TruncationCheck& c);
// A physical scene's "physical" object: its given inputs (SI, by their [physical] keys), R [m], and its times in
// seconds (the model's time unit 1/gamma: time_unit_s, T_s, dt_s). Nothing for a dimensionless scene.
void put_physical(nlohmann::json& j, const Scene& s);
// The given inputs of a cell (SI), by their [physical] keys.
nlohmann::json to_json(const PhysicalCell& c);
void put_truncation(nlohmann::json& j, int L, const std::string& L_reason);
// A double, or null when not finite.
nlohmann::json number_or_null(double v);
// `text` parsed as JSON; text that is not JSON throws InvalidArgument(parameter, "'<source>' is not JSON: ...").
nlohmann::json parse_json_text(const std::string& text, const std::string& source, const std::string& parameter);
// A complex number as [re, im], each part as number_or_null writes it.
nlohmann::json complex_json(std::complex<double> z);
// The CSV counterpart: the shortest text that reads back exactly, or an empty field when not finite -- never "nan";
// the row's or the file's status says why.
std::string csv_number(double v);
// j[key] = v, or null plus j[key + "_reason"] = reason when v is not finite.
void put_number(nlohmann::json& j, const std::string& key, double v, const std::string& reason);
// Every null or non-finite number in j (recursively), and every array holding one, gets the sibling
// "<key>_reason" = reason unless it already has one: no output hides a non-finite value without saying why.
// Non-finite numbers become null (nlohmann writes them as null anyway).
void explain_nulls(nlohmann::json& j, const std::string& reason);
// The paths ("a/b/c") of nulls with no "<key>_reason" sibling: empty for every document explain_nulls saw.
std::vector<std::string> unexplained_nulls(const nlohmann::json& j);

}  // namespace rbcstab
