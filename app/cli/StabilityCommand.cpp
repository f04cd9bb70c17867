// parallax-cli stability: the named suite of stiff and extreme cases
// (core/include/parallax/eval/StabilitySuite.h), one pass/fail row per case and technique.
// Exits non-zero if any row fails.

#include "Cli.h"
#include "CommonOptions.h"
#include "parallax/eval/StabilitySuite.h"
#include "parallax/io/AtomicWrite.h"

#include <cstdio>
#include <iostream>
#include <memory>

namespace px::cli {

namespace {

struct StabilityOptionsCli {
    std::vector<std::string> cases;
    int rays = 32;
    unsigned seed = 1;
    bool list = false;
    std::string csv;
};

// RFC 4180 quoting for the free-text columns.
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos)
        return text;
    std::string quoted = "\"";
    for (char c : text)
        quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

const char* resultWord(const StabilityRow& r) {
    return r.passed ? "pass" : "FAIL";
}

std::string stabilityCsv(const std::vector<StabilityRow>& rows) {
    std::string csv = "case,technique,result,figure,failure,p99_error,max_error,wrong_surface,"
                      "invalid,mean_fetches,p99_fetches,max_fetches,fetch_cap\n";
    char numbers[200];
    for (const StabilityRow& r : rows) {
        std::snprintf(numbers, sizeof numbers, "%.9g,%.9g,%lld,%lld,%.9g,%.9g,%d,%lld",
                      r.stats.p99Error, r.stats.maxError,
                      static_cast<long long>(r.stats.wrongSurface),
                      static_cast<long long>(r.stats.invalid), r.stats.meanFetches,
                      r.stats.p99Fetches, r.stats.maxFetches, static_cast<long long>(r.fetchCap));
        csv += csvField(r.caseName) + "," + r.technique + "," + resultWord(r) + "," +
               csvField(r.figure) + "," + csvField(r.failure) + "," + numbers + "\n";
    }
    return csv;
}

void printList() {
    std::printf("Cases:\n");
    for (const StabilityCaseInfo& c : stabilityCases())
        std::printf("  %-30s %s\n", c.name.data(), std::string(c.description).c_str());
    std::printf("\nError bounds (every row also needs finite hits, t in [0, 1] and fetches within "
                "the cap):\n");
    for (const BoundRule& r : boundRules())
        std::printf("  %-13s %s\n", info(r.technique).name.data(), std::string(r.rule).c_str());
}

int runStability(const StabilityOptionsCli& o) {
    if (o.list) {
        printList();
        return 0;
    }
    StabilityOptions options;
    options.cases = o.cases;
    options.rays = o.rays;
    options.seed = o.seed;
    Result<std::vector<StabilityRow>> rows = runStabilitySuite(options);
    if (!rows)
        return fail(rows.error().message);

    int failed = 0;
    std::printf("%-30s %-13s %-6s %s\n", "case", "technique", "result", "figure checked");
    for (const StabilityRow& r : *rows) {
        std::string note;
        if (!r.passed)
            note = "  <- " + r.failure;
        std::printf("%-30s %-13s %-6s %s%s\n", r.caseName.c_str(), r.technique.c_str(),
                    resultWord(r), r.figure.c_str(), note.c_str());
        failed += r.passed ? 0 : 1;
    }
    std::printf("%zu checks: %zu passed, %d failed\n", rows->size(), rows->size() - failed, failed);
    if (!o.csv.empty()) {
        if (Status s = writeTextFile(o.csv, stabilityCsv(*rows)); !s)
            return fail(s.error().message);
    }
    return suitePassed(*rows) ? 0 : 1;
}

} // namespace

Action addStabilityCommand(CLI::App& app) {
    auto o = std::make_shared<StabilityOptionsCli>();
    CLI::App* cmd = app.add_subcommand(
        "stability", "Run the named stiff and extreme cases with every technique: pass/fail per "
                     "case with the figure checked; exits non-zero on any failure");
    std::vector<std::string> names;
    for (const StabilityCaseInfo& c : stabilityCases())
        names.emplace_back(c.name);
    cmd->add_option("--case", o->cases, "Only these cases (comma-separated)")
        ->delimiter(',')
        ->check(CLI::IsMember(names));
    cmd->add_option("--rays", o->rays, "Rays per side (R) of each case")->check(inRange(1, 1024));
    cmd->add_option("--seed", o->seed,
                    "Seed of the maps with random texels (the adversarial ones)");
    cmd->add_flag("--list", o->list,
                  "List the cases and each technique's error bound, run nothing");
    cmd->add_option("--csv", o->csv, "Also write the rows as CSV");
    return [o] { return runStability(*o); };
}

} // namespace px::cli
