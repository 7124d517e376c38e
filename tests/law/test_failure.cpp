// The SDV-21 failure table (src/mortar/failure.hpp, docs/model.md 9).
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "mortar/failure.hpp"

using namespace mortar;

TEST_CASE("Failure table: one row per code 0-7, each naming its enum value", "[failure]") {
  std::set<int> codes;
  std::set<std::string> names;
  for (const FailureInfo& f : kFailureTable) {
    CHECK(f.code == static_cast<int>(f.failure));
    codes.insert(f.code);
    names.insert(f.name);
    REQUIRE(failure_info(f.code) == &f);
    CHECK(std::string(failure_name(f.failure)) == f.message);
  }
  CHECK(codes.size() == size_t(kFailureCount));
  CHECK(names.size() == size_t(kFailureCount));
  CHECK(*codes.begin() == 0);
  CHECK(*codes.rbegin() == kFailureCount - 1);
}

TEST_CASE("Failure table: codes the law does not produce have no row", "[failure]") {
  CHECK(failure_info(-1) == nullptr);  // an adapter's argument error
  CHECK(failure_info(kFailureCount) == nullptr);
  CHECK(std::string(failure_name(static_cast<Failure>(42))) == "unknown");
}

TEST_CASE("Failure table: the messages the logs and docs quote", "[failure]") {
  CHECK(std::string(failure_name(Failure::non_finite_increment)) == "separation increment is not finite");
  CHECK(std::string(failure_name(Failure::too_many_substeps)) == "too many substeps");
  CHECK(std::string(failure_info(7)->name) == "local_solve_failed");
}
