#pragma once
// Expects `read` to throw BadInputError whose message contains `expected`.

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/error.hpp"

namespace littermap::test {

inline void ExpectBadInput(const std::function<void()>& read, const std::string& expected) {
  try {
    read();
    ADD_FAILURE() << "no error, expected " << expected;
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

}  // namespace littermap::test
