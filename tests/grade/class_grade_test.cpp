// A class graded in one command (`impulse grade FOLDER --jobs 2 --csv --gradescope --junit`): a
// folder of 20 submissions (the corrected listing, the listing as printed with its parentheses
// fixed, one that does not compile, one that reads /etc/passwd, some as files and some in folders
// of their own, one folder with no .cpp), and the three outputs read back.
#include "tests/support/child_process.h"
#include "tests/support/response_files.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace impulse::workshop {
namespace {

namespace fs = std::filesystem;

// A CSV line's fields (RFC 4180 quoting).
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// How many times `what` is in `text`.
size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

struct Expected {
  int score;
  bool compiled;
};

TEST(ClassGrade, TwentySubmissionsInOneCommandWithTheirCsvGradescopeAndJunit) {
  const fs::path dir = fs::path(IMPULSE_TEST_SCRATCH) / "class_grade";
  fs::remove_all(dir);
  const fs::path folder = dir / "submissions";
  fs::create_directories(folder);
  std::map<std::string, Expected> expected;
  // Nine corrected, nine printed: every other one in a folder of its own, as GitHub Classroom has them.
  for (int i = 0; i < 18; ++i) {
    const bool corrected = i % 2 == 0;
    const std::string student = (corrected ? "corrected_" : "printed_") + std::to_string(i / 2);
    const fs::path file = i % 4 < 2 ? folder / (student + ".cpp") : folder / student / "collision.cpp";
    fs::create_directories(file.parent_path());
    fs::copy_file(test::listing(corrected ? "listing1_corrected.cpp" : "listing1.cpp"), file);
    expected[student] = {corrected ? 13 : 2, true};
  }
  fs::copy_file(test::listing("listing1_printed.cpp"), folder / "not_compiling.cpp");
  expected["not_compiling"] = {0, false};
  std::ofstream(folder / "hostile.cpp") << test::read(std::string(IMPULSE_SOURCE_DIR) + "/tests/response/hostile/run/read_file.cpp")
                                        << "static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, "
                                           "const Vector3& normal, float penetration) { Hostile(); }\n";
  expected["hostile"] = {0, true};
  fs::create_directories(folder / "empty_folder");
  expected["empty_folder"] = {0, false};
  std::ofstream(folder / "README.txt") << "not a submission\n";

  const fs::path out = dir / "table.txt";
  const std::string command = "exec '" + std::string(IMPULSE_PROGRAM) + "' grade '" + folder.string() + "' --jobs 2 --regrade --csv '" +
                              (dir / "grades.csv").string() + "' --gradescope '" + (dir / "gradescope").string() + "' --junit '" +
                              (dir / "grades.xml").string() + "' > '" + out.string() + "'";
  const auto result = ::impulse::testing::run_child({"/bin/sh", "-c", command});
  EXPECT_EQ(result.exit_code, 2) << result.describe();  // some failed
  const std::string table = test::read(out.string());
  EXPECT_NE(table.find("21 submissions, 19 compile, 9 pass every case"), std::string::npos) << table;
  EXPECT_NE(table.find("not_compiling   0/13  does not compile: " + (folder / "not_compiling.cpp").string() + ":77:"), std::string::npos) << table;
  EXPECT_NE(table.find("every case (AddCollisionImpulse tried to open a file ('/etc/passwd'), which graded code may not do)"), std::string::npos)
      << table;
  EXPECT_EQ(table.find("root:x:0:0"), std::string::npos) << table;

  // The CSV: a row per student with its score, and a column per case.
  std::istringstream csv(test::read((dir / "grades.csv").string()));
  std::string line;
  std::getline(csv, line);
  const std::vector<std::string> header = csv_fields(line);
  ASSERT_GE(header.size(), 19u);
  EXPECT_EQ(std::vector<std::string>(header.begin(), header.begin() + 7),
            (std::vector<std::string>{"student", "file", "score", "max_score", "compiled", "failed_cases", "message"}));
  EXPECT_EQ(header[7], "head_on_equal_e0");
  std::map<std::string, std::vector<std::string>> rows;
  while (std::getline(csv, line)) rows[csv_fields(line)[0]] = csv_fields(line);
  ASSERT_EQ(rows.size(), expected.size());
  for (const auto& [student, want] : expected) {
    const std::vector<std::string>& row = rows[student];
    ASSERT_EQ(row.size(), header.size()) << student;
    EXPECT_EQ(row[2], std::to_string(want.score)) << student;
    EXPECT_EQ(row[3], "13") << student;
    EXPECT_EQ(row[4], want.compiled ? "1" : "0") << student;
  }
  EXPECT_EQ(rows["printed_0"][5], "head_on_equal_e0.7;head_on_equal_e1;head_on_unequal_e0.7;head_on_unequal_e1;off_centre_spin;oblique;"
                                  "ball_rest;slide_friction;slide_frictionless;bounce_spin;stack");
  EXPECT_EQ(rows["printed_1"][1], (folder / "printed_1" / "collision.cpp").string());
  EXPECT_NE(rows["not_compiling"][6].find("error:"), std::string::npos) << rows["not_compiling"][6];
  EXPECT_EQ(rows["empty_folder"][6], "no .cpp file in the folder");
  EXPECT_EQ(rows["hostile"][7], "0");

  // Gradescope: a results.json per student, a test per case.
  for (const auto& [student, want] : expected) {
    const fs::path path = dir / "gradescope" / student / "results.json";
    ASSERT_TRUE(fs::exists(path)) << path;
    const nlohmann::json results = nlohmann::json::parse(test::read(path.string()));
    EXPECT_EQ(results["score"].get<double>(), double(want.score)) << student;
    ASSERT_EQ(results["tests"].size(), want.compiled ? 13u : 0u) << student;
    int passed = 0;
    for (const auto& test : results["tests"]) {
      EXPECT_EQ(test["max_score"].get<double>(), 1.0);
      EXPECT_EQ(test["status"], test["score"].get<double>() == 1.0 ? "passed" : "failed");
      EXPECT_NE(test["output"].get<std::string>().find("law: "), std::string::npos);
      passed += test["status"] == "passed";
    }
    EXPECT_EQ(passed, want.score) << student;
  }
  const nlohmann::json printed = nlohmann::json::parse(test::read((dir / "gradescope/printed_0/results.json").string()));
  EXPECT_NE(printed["tests"][1]["output"].get<std::string>().find("hint: "), std::string::npos) << printed.dump(2);
  const nlohmann::json broken = nlohmann::json::parse(test::read((dir / "gradescope/not_compiling/results.json").string()));
  EXPECT_NE(broken["output"].get<std::string>().find("not_compiling.cpp:77:"), std::string::npos) << broken.dump(2);

  // JUnit: a suite per student, "compile" and the thirteen cases in each graded one.
  const std::string xml = test::read((dir / "grades.xml").string());
  EXPECT_EQ(count(xml, "<testsuite name="), expected.size());
  EXPECT_EQ(count(xml, "<testcase "), expected.size() + 19 * 13u);
  // failures: 9 printed x 11, the hostile's 13, and two that were not graded
  EXPECT_EQ(count(xml, "<failure "), 9 * 11 + 13 + 2u);
  EXPECT_NE(xml.find("<testsuites name=\"impulse grade " + folder.string() + "\" tests=\"268\" failures=\"114\">"), std::string::npos)
      << xml.substr(0, 300);
  EXPECT_NE(xml.find("tried to open a file ('/etc/passwd')"), std::string::npos);
}

// A re-run grades only what changed: each result is kept by the file's text, the program and the
// time limit; --regrade grades everything again. The table is the same each time.
TEST(ClassGrade, ARerunGradesOnlyWhatChanged) {
  const fs::path dir = fs::path(IMPULSE_TEST_SCRATCH) / "class_rerun";
  fs::remove_all(dir);
  const fs::path folder = dir / "submissions";
  fs::create_directories(folder);
  fs::copy_file(test::listing("listing1_corrected.cpp"), folder / "ada.cpp");
  fs::copy_file(test::listing("listing1.cpp"), folder / "bo.cpp");
  auto grade = [&](const std::string& extra) {
    const std::string command = "IMPULSE_RESPONSE_CACHE='" + (dir / "cache").string() + "' exec '" + std::string(IMPULSE_PROGRAM) +
                                "' grade '" + folder.string() + "' --jobs 2" + extra + " > '" + (dir / "table.txt").string() + "' 2> '" +
                                (dir / "progress.txt").string() + "'";
    const auto result = ::impulse::testing::run_child({"/bin/sh", "-c", command});
    EXPECT_EQ(result.exit_code, 2) << result.describe();  // bo fails cases
    return std::pair{test::read((dir / "table.txt").string()), test::read((dir / "progress.txt").string())};
  };
  const auto [first_table, first] = grade("");
  EXPECT_NE(first.find("[2/2]"), std::string::npos) << first;
  EXPECT_EQ(first.find("unchanged"), std::string::npos) << first;
  const auto [second_table, second] = grade("");
  EXPECT_NE(second.find("2 unchanged since they were graded"), std::string::npos) << second;
  EXPECT_EQ(second.find("[1/"), std::string::npos) << second;
  EXPECT_EQ(second_table, first_table);
  std::ofstream(folder / "bo.cpp", std::ios::app) << "// a comment: another text, graded again\n";
  const auto [third_table, third] = grade("");
  EXPECT_NE(third.find("1 unchanged since they were graded"), std::string::npos) << third;
  EXPECT_NE(third.find("[1/1] bo: 2 of 13 cases"), std::string::npos) << third;
  EXPECT_EQ(third_table, first_table);
  const auto [fourth_table, fourth] = grade(" --regrade");
  EXPECT_NE(fourth.find("[2/2]"), std::string::npos) << fourth;
  EXPECT_EQ(fourth.find("unchanged"), std::string::npos) << fourth;
  EXPECT_EQ(fourth_table, first_table);
}

}  // namespace
}  // namespace impulse::workshop
