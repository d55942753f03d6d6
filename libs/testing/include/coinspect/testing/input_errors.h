// Checking the InputError a test provokes: its message, and whether the message names something.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "coinspect/core/error.h"

namespace coinspect::testing {

// The message of the InputError that f() throws; records a failure and returns "" if none is.
template <class F>
std::string messageOf(F&& f) {
  try {
    f();
  } catch (const ::coinspect::InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return "";
}

}  // namespace coinspect::testing

// Expects `message` to contain `text`, printing both when it does not.
#define EXPECT_MENTIONS(message, text)               \
  EXPECT_NE((message).find(text), std::string::npos) \
      << "'" << (message) << "' lacks '" << (text) << "'"
