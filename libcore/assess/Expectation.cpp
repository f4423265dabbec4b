#include "assess/Expectation.hpp"

#include "io/JsonInput.hpp"
#include "io/JsonText.hpp"

#include <cmath>
#include <cstdio>

namespace hvi::assess {

using nlohmann::json;

namespace {

/// Every object holding a string "id" and an object "expected", by JSON pointer.
void collectCases(const json& node, const std::string& pointer,
                  std::vector<std::pair<std::string, const json*>>& cases) {
    if (node.is_object()) {
        const auto id = node.find("id");
        const auto expected = node.find("expected");
        if (id != node.end() && id->is_string() && expected != node.end() &&
            expected->is_object()) {
            cases.emplace_back(pointer, &node);
            return;
        }
        for (const auto& [key, value] : node.items()) {
            collectCases(value, pointer + "/" + key, cases);
        }
    } else if (node.is_array()) {
        for (std::size_t k = 0; k < node.size(); ++k) {
            collectCases(node[k], pointer + "/" + std::to_string(k), cases);
        }
    }
}

std::string caseList(const std::vector<std::pair<std::string, const json*>>& cases) {
    std::string list;
    for (const auto& [pointer, node] : cases) {
        list += (list.empty() ? "" : ", ") + (*node)["id"].get<std::string>();
    }
    return list.empty() ? std::string("none") : list;
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

std::string valueText(const json& v) {
    if (v.is_number()) {
        return number(v.get<double>());
    }
    if (v.is_string()) {
        return v.get<std::string>();
    }
    return io::jsonText(v);
}

} // namespace

ExpectedBlock selectExpected(const json& document, const std::string& file,
                             const std::optional<std::string>& caseId, const std::string& sceneId) {
    ExpectedBlock picked;
    picked.file = file;
    std::vector<std::pair<std::string, const json*>> cases;
    collectCases(document, "", cases);
    if (caseId) {
        for (const auto& [pointer, node] : cases) {
            if ((*node)["id"] == *caseId) {
                picked.block = (*node)["expected"];
                picked.caseId = caseId;
                picked.pointer = pointer + "/expected";
                break;
            }
        }
        if (!picked.caseId) {
            throw InputError(file, "", "no case with id '" + *caseId + "'",
                             "one of: " + caseList(cases));
        }
    } else if (document.is_object() && document.contains("pnp")) {
        picked.block = document;
    } else if (cases.size() == 1 && cases.front().first.empty()) {
        const json& node = *cases.front().second;
        picked.block = node["expected"];
        picked.caseId = node["id"].get<std::string>();
        picked.pointer = "/expected";
    } else {
        for (const auto& [pointer, node] : cases) {
            if ((*node)["id"] == sceneId) {
                picked.block = (*node)["expected"];
                picked.caseId = sceneId;
                picked.pointer = pointer + "/expected";
                break;
            }
        }
        if (!picked.caseId) {
            throw InputError(file, "",
                             cases.empty() ? "holds no expected block"
                                           : "holds several cases and none has the run's scene "
                                             "id '" +
                                                 sceneId + "'",
                             cases.empty() ? "an object with \"pnp\" or a case with \"expected\""
                                           : "--case ID with ID one of: " + caseList(cases));
        }
    }
    try {
        io::validateAgainstSchema(picked.block, "expected", file);
    } catch (const InputError& e) {
        std::vector<InputIssue> issues = e.issues();
        for (auto& issue : issues) {
            issue.pointer = picked.pointer + issue.pointer;
        }
        throw InputError(std::move(issues));
    }
    return picked;
}

Expectation compareWithExpected(const ExpectedBlock& expected, const Assessment& a,
                                const std::set<std::string>& only) {
    Expectation result;
    result.caseId = expected.caseId;
    result.source = expected.file;
    const json& block = expected.block;
    auto wanted = [&](const std::string& q) {
        return (only.empty() || only.count(q)) && block.contains(q) && !block[q].is_null();
    };

    if (wanted("pnp")) {
        ExpectationCheck c;
        c.quantity = "pnp";
        c.expected = block["pnp"];
        c.actual = a.failed ? json(*a.failed ? "P" : "NP") : json(nullptr);
        c.passed = c.actual == c.expected;
        result.checks.push_back(c);
    }
    struct Metric {
        const char* key;
        std::optional<double> actual;
        double rtol, atol;
    };
    const double holeBin = a.last().hole ? a.last().hole->binWidthMm : 0.0;
    const Metric metrics[] = {
        {"penetration_depth_mm", a.penetrationDepthMm, DefaultTolerances::depthRtol, 0.0},
        {"bumper_hole_diameter_mm",
         a.last().hole ? std::optional<double>(a.last().hole->diameterMm) : std::nullopt,
         DefaultTolerances::holeRtol, DefaultTolerances::holeAtolBins * holeBin},
        {"core_damage_width_mm", a.coreDamageWidthMm, DefaultTolerances::widthRtol, 0.0},
    };
    for (const auto& m : metrics) {
        if (!wanted(m.key)) {
            continue;
        }
        ExpectationCheck c;
        c.quantity = m.key;
        c.expected = block[m.key];
        const double want = block[m.key].get<double>();
        double rtol = m.rtol, atol = m.atol;
        if (block.contains("tolerances") && block["tolerances"].contains(m.key)) {
            const json& t = block["tolerances"][m.key];
            rtol = t.value("rtol", rtol);
            atol = t.value("atol", atol);
        }
        c.allowed = atol + rtol * std::fabs(want);
        if (m.actual) {
            c.actual = *m.actual;
            c.difference = *m.actual - want;
            c.passed = std::fabs(*c.difference) <= *c.allowed;
        } else {
            c.actual = nullptr;
            c.passed = false;
        }
        result.checks.push_back(c);
    }
    for (const auto& c : result.checks) {
        result.passed = result.passed && c.passed;
    }
    return result;
}

std::string Expectation::reportLine() const {
    std::string line = "expect " + caseId.value_or(source) + ": " + (passed ? "PASS" : "FAIL");
    if (checks.empty()) {
        return line + ": nothing to compare";
    }
    std::string sep = ": ";
    for (const auto& c : checks) {
        line += sep + c.quantity + " " +
                (c.actual.is_null() ? std::string("not assessed") : valueText(c.actual)) +
                " (expected " + valueText(c.expected);
        if (c.difference) {
            line += ", diff " + number(*c.difference) + ", allowed " + number(*c.allowed);
        }
        line += std::string(") ") + (c.passed ? "ok" : "MISMATCH");
        sep = "; ";
    }
    return line;
}

json Expectation::toJson() const {
    json checksJson = json::array();
    for (const auto& c : checks) {
        json j = {{"quantity", c.quantity},
                  {"expected", c.expected},
                  {"actual", c.actual},
                  {"passed", c.passed}};
        if (c.difference) {
            j["difference"] = *c.difference;
            j["allowed"] = *c.allowed;
        }
        checksJson.push_back(j);
    }
    return {{"case", caseId ? json(*caseId) : json(nullptr)},
            {"source", source},
            {"passed", passed},
            {"checks", checksJson}};
}

} // namespace hvi::assess
