// Unit tests of the driver helpers: atomic CSV, non-finite refusal, claims
// quoting, --out parsing, command-line checks, column tables, the shared main.
#include <catch2/catch.hpp>  // main(): Catch2::Catch2WithMain (CMakeLists.txt)

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>  // getpid

#include "repro/common/common.hpp"
#include "repro/common/options.hpp"

namespace fs = std::filesystem;

namespace {
std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
std::string scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("repro_common_test_" + std::to_string(::getpid()));
  return (d / name).string();
}
}  // namespace

TEST_CASE("CsvWriter writes only on commit, creating directories", "[csv]") {
  const std::string path = scratch("a/b/t.csv");
  {
    repro::CsvWriter w(path, {"x", "y"}, {"a note"});
    w.row({0.1, 1e-300});
    w.row(std::vector<std::string>{"has,comma", "has\"quote"});
    CHECK_FALSE(fs::exists(path));
    CHECK(fs::exists(path + ".tmp"));
    w.commit();
  }
  CHECK(fs::exists(path));
  CHECK_FALSE(fs::exists(path + ".tmp"));
  CHECK(slurp(path) == "# a note\nx,y\n0.1,1e-300\n\"has,comma\",\"has\"\"quote\"\n");
  fs::remove_all(fs::path(scratch("")));
}

TEST_CASE("CsvWriter without commit leaves nothing", "[csv]") {
  const std::string path = scratch("u.csv");
  { repro::CsvWriter w(path, {"x"}); w.row({1.0}); }
  CHECK_FALSE(fs::exists(path));
  CHECK_FALSE(fs::exists(path + ".tmp"));
  fs::remove_all(fs::path(scratch("")));
}

TEST_CASE("CsvWriter refuses non-finite values and names the column", "[csv]") {
  const std::string path = scratch("n.csv");
  {
    repro::CsvWriter w(path, {"time", "velocity"});
    w.row({0.0, 1.0});
    try {
      w.row({1.0, std::nan("")});
      FAIL("no exception");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()).find("'velocity'") != std::string::npos);
    }
    CHECK_THROWS_AS(w.row({1.0, INFINITY}), std::invalid_argument);
    CHECK_THROWS_AS(w.row({1.0}), std::invalid_argument);  // wrong width
  }
  CHECK_FALSE(fs::exists(path));
  fs::remove_all(fs::path(scratch("")));
}

TEST_CASE("full-precision numbers read back exactly", "[csv]") {
  for (double v : {0.1, 1.0 / 3.0, -2.5e-17, 6.02214076e23, 5e-324})
    CHECK(std::strtod(repro::format_full(v).c_str(), nullptr) == v);
}

TEST_CASE("claims file has the report's columns, scopes, kinds, ids and causes", "[claims]") {
  const std::string out = scratch("o");
  const std::string path = repro::claims_path(out, "drv");
  repro::Claim fail{"4.1", "c", "\"q\"", "3", "<2", false};
  repro::explain_fail(fail, repro::Root::kUnstatedSetup, "geometry reconstructed");
  fail.scope = repro::Scope::kPaper;
  repro::Claim pass{"4.1", "a, b", "x", "1", "<2", true};
  pass.control = "ctl";
  pass.scope = repro::Scope::kOption;
  repro::explain_fail(pass, repro::Root::kUnexplained, "ignored: the check passes");
  repro::Claim fitted{"B-6", "f", "p", "0.34", "~0.34", true};
  fitted.fitted = true;
  fitted.control = "ctl";
  fitted.scope = repro::Scope::kPaper;
  repro::Claim reading{"B-6", "r", "p", "0.4", "<1e-12", false};
  repro::explain_fail(reading, repro::Root::kSubModelReading, "momentum drifts");
  reading.scope = repro::Scope::kPaper;
  std::vector<repro::Claim> rows = {pass, fail, fitted, reading,
                                    repro::measurement("5.1", "H (m)", "-", "0.5", "information"),
                                    repro::measurement("5.1", "H (m)", "-", "0.6", "information")};
  repro::default_scope(rows, repro::Scope::kExtension);  // the measurements only: the others have one
  repro::write_claims(path, rows);
  std::string text = slurp(path);
  // The run time is the last column; drop its values before comparing.
  std::string stripped;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t eol = text.find('\n', pos);
    const std::string line = text.substr(pos, eol - pos);
    stripped += pos == 0 ? line : line.substr(0, line.rfind(','));
    stripped += '\n';
    pos = eol + 1;
  }
  CHECK(stripped ==
        "id,section,scope,kind,claim,paper,measured,tolerance,status,cause,root_cause,cause_text,control,run_time_s\n"
        "4.1:a-b,4.1,option,check,\"a, b\",x,1,<2,PASS,,,,ctl\n"
        "4.1:c,4.1,paper,check,c,\"\"\"q\"\"\",3,<2,FAIL,missing_data,unstated_setup,geometry reconstructed,\n"
        "B-6:f,B-6,paper,fitted,f,p,0.34,~0.34,PASS,,,,ctl\n"
        "B-6:r,B-6,paper,check,r,p,0.4,<1e-12,FAIL,our_reading,sub_model_reading,momentum drifts,\n"
        "5.1:h-m,5.1,extension,measurement,H (m),-,0.5,information,,,,,\n"
        "5.1:h-m-2,5.1,extension,measurement,H (m),-,0.6,information,,,,,\n");
  // A row without a scope is refused, naming it; nothing is written.
  const std::string bad = repro::claims_path(out, "bad");
  repro::Claim none{"6.2", "no scope", "p", "1", "<2", true};
  try {
    repro::write_claims(bad, {pass, none});
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find("6.2:no-scope has no scope") != std::string::npos);
  }
  CHECK_FALSE(fs::exists(bad));
  fs::remove_all(fs::path(scratch("")));
}

TEST_CASE("every root cause has a name and a category", "[claims]") {
  using repro::Root;
  for (Root r : {Root::kFrictionStartUp, Root::kFrictionUpdate, Root::kSegmentation, Root::kThinBlock,
                 Root::kSmallGeometryStep, Root::kStiffBounce, Root::kCloneImpact, Root::kNodalPeak,
                 Root::kMeshDispersion, Root::kSubModelReading, Root::kUnstatedSetup, Root::kPrintedNumbers,
                 Root::kCornerNormal, Root::kUnexplained}) {
    CHECK_FALSE(repro::root_name(r).empty());
    CHECK(repro::root_cause(r) != repro::Cause::kNone);
  }
  CHECK(repro::root_cause(Root::kSubModelReading) == repro::Cause::kOurReading);
  CHECK(repro::cause_name(repro::Cause::kOurReading) == "our_reading");
}

TEST_CASE("claim ids: explicit key, or a bounded slug of the claim", "[claims]") {
  repro::Claim c{"6.2", "The Left slope SLUMPS (phi = 30 deg)!", "", "", "", false};
  CHECK(repro::claim_id(c) == "6.2:the-left-slope-slumps-phi-30-deg");
  c.key = "slump";
  CHECK(repro::claim_id(c) == "6.2:slump");
  c.key.clear();
  c.claim = std::string(200, 'x');
  CHECK(repro::claim_id(c).size() < 100);
}

TEST_CASE("out_dir parses --out", "[cli]") {
  char a0[] = "prog", a1[] = "--out", a2[] = "dir1", a3[] = "--out=dir2", a4[] = "--other";
  char* v1[] = {a0};
  CHECK(repro::out_dir(1, v1) == "out");
  char* v2[] = {a0, a1, a2};
  CHECK(repro::out_dir(3, v2) == "dir1");
  char* v3[] = {a0, a4, a3};
  CHECK(repro::out_dir(3, v3) == "dir2");
  char* v4[] = {a0, a1};
  CHECK_THROWS_AS(repro::out_dir(2, v4), std::invalid_argument);
}

TEST_CASE("command_line_error names an unknown option, a stray argument and a bad value", "[cli]") {
  const std::initializer_list<repro::OptionHelp> options = {{"--duration", "S", "seconds", false},
                                                            {"--threads", "N", "threads", true}};
  auto error = [&](std::vector<std::string> args) {
    args.insert(args.begin(), "prog");
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    return repro::command_line_error(static_cast<int>(argv.size()), argv.data(), options);
  };
  CHECK(error({}) == "");
  CHECK(error({"--out", "d", "--duration", "0.5", "--threads=2", "--help"}) == "");
  CHECK(error({"--out=d", "--duration=-1e-3", "--threads", "-3"}) == "");  // ranges are the driver's to check
  CHECK(error({"--durration", "1"}) == "unknown option '--durration' (this driver takes --out, --duration, --threads, --help)");
  CHECK(error({"--threads=2", "extra"}).rfind("unexpected argument 'extra'", 0) == 0);
  CHECK(error({"-x"}).rfind("unknown option '-x'", 0) == 0);
  CHECK(error({"--duration"}) == "--duration needs a value");
  CHECK(error({"--duration="}) == "--duration needs a value");
  CHECK(error({"--duration", "2s"}) == "--duration not a finite number: '2s'");
  CHECK(error({"--duration", "nan"}) == "--duration not a finite number: 'nan'");
  CHECK(error({"--threads", "1.5"}) == "--threads not a whole number: '1.5'");
  CHECK(error({"--out"}) == "--out needs a directory");
  CHECK(error({"--out="}) == "--out needs a directory");
  CHECK(error({"--duration", "1", "--out"}) == "--out needs a directory");
  CHECK(error({"--duration", "--out", "d"}) == "--duration needs a value");  // an option is no value
  CHECK(error({"--out", "--duration", "1"}) == "--out needs a directory");
}

TEST_CASE("option_text reads arguments as the command-line check does", "[cli]") {
  std::vector<std::string> args = {"prog", "--threads", "--out", "d", "--case", "-3", "--case=2", "--duration="};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  const int argc = static_cast<int>(argv.size());
  std::string v = "unset";
  CHECK(repro::option_text(argc, argv.data(), "--threads", v));
  CHECK(v == "");  // followed by an option: no value
  CHECK(repro::out_dir(argc, argv.data()) == "d");
  CHECK(repro::option_text(argc, argv.data(), "--case", v));
  CHECK(v == "2");  // the last one given
  CHECK(repro::option_text(argc, argv.data(), "--duration", v));
  CHECK(v == "");
  CHECK_FALSE(repro::option_text(argc, argv.data(), "--d", v));
  CHECK_FALSE(repro::option_text(argc, argv.data(), "d", v));
}

TEST_CASE("usage_text lists --out and every option with its help", "[cli]") {
  const std::string u = repro::usage_text("prog", "What it does.", {{"--duration", "S", "simulated seconds", false}});
  CHECK(u.rfind("usage: prog [--out DIR] [--duration S]\nWhat it does.\n", 0) == 0);
  CHECK(u.find("  --out DIR     output root") != std::string::npos);
  CHECK(u.find("  --duration S  simulated seconds\n") != std::string::npos);
}

TEST_CASE("option_number and option_int read an option's value or throw naming it", "[cli]") {
  std::vector<std::string> args = {"prog", "--duration", "0.25", "--threads=2", "--case", "x"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  const int argc = static_cast<int>(argv.size());
  CHECK(repro::option_number(argc, argv.data(), "--duration", 7.5) == 0.25);
  CHECK(repro::option_int(argc, argv.data(), "--threads", 1) == 2);
  CHECK(repro::option_int(argc, argv.data(), "--missing", 7) == 7);
  CHECK_THROWS_WITH(repro::option_int(argc, argv.data(), "--case", 0), "--case not a finite number: 'x'");
  CHECK_THROWS_WITH(repro::option_int(argc, argv.data(), "--duration", 0), "--duration not a whole number: '0.25'");
}

TEST_CASE("a column table writes the columns' names and each row's cells", "[table]") {
  struct Row {
    std::string name;
    double x;
    int n;
  };
  const std::vector<repro::Column<Row>> columns = {{"name", [](const Row& r) { return r.name; }},
                                                   {"x", [](const Row& r) { return r.x; }},
                                                   {"n", [](const Row& r) { return r.n; }}};
  const std::string path = scratch("table/mixed.csv");
  repro::write_table(path, columns, std::vector<Row>{{"a, b", 0.1, 3}, {"c", 1e-300, -2}}, {"note"});
  CHECK(slurp(path) == "# note\nname,x,n\n\"a, b\",0.1,3\nc,1e-300,-2\n");

  // A table of numbers only is written as CsvWriter writes numbers.
  const std::string numbers = scratch("table/numbers.csv");
  repro::write_table<double>(numbers, {{"x", [](double v) { return v; }}, {"twice", [](double v) { return 2 * v; }}},
                             std::vector<double>{0.5, 1.0 / 3.0});
  repro::CsvWriter same(scratch("table/same.csv"), {"x", "twice"});
  same.row({0.5, 1.0});
  same.row({1.0 / 3.0, 2.0 / 3.0});
  same.commit();
  CHECK(slurp(numbers) == slurp(scratch("table/same.csv")));
}

TEST_CASE("a column table refuses a non-finite cell, naming its column, and writes nothing", "[table]") {
  struct Row {
    std::string name;
    double x;
  };
  const std::vector<repro::Column<Row>> columns = {{"name", [](const Row& r) { return r.name; }},
                                                   {"x", [](const Row& r) { return r.x; }}};
  for (const double bad : {std::nan(""), HUGE_VAL}) {
    const std::string path = scratch("table/bad.csv");
    try {
      repro::write_table(path, columns, std::vector<Row>{{"ok", 1.0}, {"bad", bad}});
      FAIL("no exception");
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()).find("column 'x'") != std::string::npos);
      CHECK(std::string(e.what()).find("data row 2") != std::string::npos);
    }
    CHECK_FALSE(fs::exists(path));
    CHECK_FALSE(fs::exists(path + ".tmp"));
  }
}

TEST_CASE("driver_main gives the body's status, or 1 with the program's name when it throws", "[cli]") {
  char name[] = "driver";
  char out_flag[] = "--out";
  std::string dir = scratch("driver");
  char* argv[] = {name, out_flag, dir.data(), nullptr};
  std::string seen;
  CHECK(repro::driver_main(3, argv, {"driver", "test driver", "a test"}, {}, [&seen](const repro::Driver& d) {
          seen = d.out;
          return 7;
        }) == 7);
  CHECK(seen == dir);
  CHECK(repro::driver_main(3, argv, {"driver", "test driver", "a test"}, {},
                           [](const repro::Driver&) -> int { throw std::runtime_error("boom"); }) == 1);
}
