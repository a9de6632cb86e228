/**
 * \file
 * \brief The DigiView wire formats as a gtest parameter, for every test that holds in all of them:
 * INSTANTIATE_TEST_SUITE_P(Formats, Suite, ::testing::ValuesIn(digiview_test::FORMATS), digiview_test::formatName).
 */
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ptz_action_server/core/digiview/digiview_codec.h"

namespace ptz_action_server
{
namespace digiview_test
{
inline const std::vector<digiview::Format> FORMATS(std::begin(digiview::FORMATS), std::end(digiview::FORMATS));

/// "V0_5", "V1_0", "V1_1": a test name cannot hold the dot of "0.5".
inline std::string formatName(const ::testing::TestParamInfo<digiview::Format>& info)
{
  std::string name = std::string("V") + digiview::toString(info.param);
  name[2] = '_';
  return name;
}
}  // namespace digiview_test
}  // namespace ptz_action_server
