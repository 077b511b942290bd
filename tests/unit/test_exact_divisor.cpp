// ExactDivisor's quotient against the division instruction, at the edges of 32 bits and at random.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <stdexcept>

#include "cells/exact_divisor.hpp"

namespace granule {
namespace {

TEST(ExactDivisor, QuotientIsTheIntegerDivision) {
  std::mt19937_64 rng(5);
  std::vector<std::uint32_t> divisors{2, 3, 5, 7, 10, 641, 1000, 4096, 46341, 65535, 65536, 2147483647u, 4294967295u};
  for (int k = 0; k < 200; ++k) divisors.push_back(2 + static_cast<std::uint32_t>(rng() % 4294967294u));
  for (const std::uint32_t d : divisors) {
    const ExactDivisor divisor(d);
    std::vector<std::uint32_t> numbers{0, 1, d - 1, d, d + 1, 2 * d - 1, 2 * d, 4294967295u, 4294967294u, 2147483648u};
    for (int k = 0; k < 2000; ++k) numbers.push_back(static_cast<std::uint32_t>(rng()));
    for (const std::uint32_t n : numbers) ASSERT_EQ(divisor.quotient(n), n / d) << n << " / " << d;
  }
}

TEST(ExactDivisor, RefusesDivisorsBelowTwo) {
  EXPECT_THROW(ExactDivisor(0), std::invalid_argument);
  EXPECT_THROW(ExactDivisor(1), std::invalid_argument);
}

}  // namespace
}  // namespace granule
