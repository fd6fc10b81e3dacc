// The memory budget behind --max-memory (issue 12): sizes as users write them, charges refused past the
// limit without being counted, and charges given back when their owner goes.
#include "snell/memory/budget.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace snell::memory {
namespace {

TEST(MemorySize, ParsesUnitsAsPowersOf1024) {
  EXPECT_EQ(parse_size("2G"), 2ull << 30);
  EXPECT_EQ(parse_size("512M"), 512ull << 20);
  EXPECT_EQ(parse_size("64k"), 64ull << 10);
  EXPECT_EQ(parse_size("1.5GiB"), 3ull << 29);
  EXPECT_EQ(parse_size("3MB"), 3ull << 20);
  EXPECT_EQ(parse_size("1T"), 1ull << 40);
  EXPECT_EQ(parse_size("1000000"), 1000000u);
  EXPECT_EQ(parse_size("100b"), 100u);
}

TEST(MemorySize, RejectsWhatIsNotASize) {
  for (const char* bad : {"", "G", "-1G", "0", "0.1", "2X", "1.2.3M", "1e3", "2 G", "99999999999T"})
    EXPECT_FALSE(parse_size(bad).has_value()) << bad;
}

TEST(MemorySize, FormatsReadably) {
  EXPECT_EQ(format_size(100), "100 bytes");
  EXPECT_EQ(format_size(1536), "1.5 KiB");
  EXPECT_EQ(format_size(512ull << 20), "512 MiB");
  EXPECT_EQ(format_size(3ull << 30), "3.0 GiB");
}

TEST(MemoryBudget, RefusesAChargePastTheLimitAndCountsNothingForIt) {
  Budget budget(1000);
  budget.charge(600, "first");
  try {
    budget.charge(500, "mesh2 face_indices");
    FAIL() << "no BudgetExceeded";
  } catch (const BudgetExceeded& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("mesh2 face_indices needs 500 bytes"), std::string::npos) << message;
    EXPECT_NE(message.find("1000 bytes memory limit"), std::string::npos) << message;
    EXPECT_NE(message.find("600 bytes already in use"), std::string::npos) << message;
  }
  EXPECT_EQ(budget.used(), 600u);
  budget.charge(400, "exactly to the limit");
  EXPECT_EQ(budget.used(), 1000u);
  EXPECT_EQ(budget.peak(), 1000u);
  budget.release(1000);
  EXPECT_EQ(budget.used(), 0u);
  EXPECT_EQ(budget.peak(), 1000u);
}

TEST(MemoryBudget, HugeChargesDoNotWrapAround) {
  Budget budget(Budget::kUnlimited - 10);
  budget.charge(100, "a");
  EXPECT_THROW(budget.charge(Budget::kUnlimited - 50, "b"), BudgetExceeded);
  EXPECT_EQ(budget.used(), 100u);
}

TEST(MemoryCharge, IsGivenBackWhenItsOwnerGoesAndChargedAgainWhenCopied) {
  auto budget = std::make_shared<Budget>(800);
  {
    Charge a(budget, 300, "array");
    EXPECT_EQ(budget->used(), 300u);
    Charge b = a;  // a copied array holds its own items
    EXPECT_EQ(budget->used(), 600u);
    Charge c = std::move(b);
    EXPECT_EQ(budget->used(), 600u);
    EXPECT_THROW(Charge d = a, BudgetExceeded) << "a third copy passes the limit";
    EXPECT_EQ(budget->used(), 600u);
  }
  EXPECT_EQ(budget->used(), 0u);
}

TEST(MemoryBudget, DefaultLeavesAQuarterOfPhysicalMemory) {
  const uint64_t physical = physical_memory_bytes();
  ASSERT_GT(physical, 0u);
  EXPECT_EQ(default_limit(), physical / 4 * 3);
}

}  // namespace
}  // namespace snell::memory
