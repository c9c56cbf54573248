#pragma once
// The whole virtual rutting test in one include: its definition
// (protocol/rutting/test.hpp), material model (protocol/rutting/materials.hpp; the frozen 3D
// model's, protocol/rutting/model3.hpp), measurements
// (protocol/rutting/result.hpp) and run (protocol/rutting/run.hpp, by the one
// driver of 2D and 3D, protocol/rutting/driver.hpp).
#include <vrut/protocol/rutting/materials.hpp>
#include <vrut/protocol/rutting/model3.hpp>
#include <vrut/protocol/rutting/result.hpp>
#include <vrut/protocol/rutting/run.hpp>
#include <vrut/protocol/rutting/test.hpp>
