#pragma once
// The whole virtual rutting test in one include: its definition
// (rutting/test.hpp), material model (rutting/materials.hpp), measurements
// (rutting/result.hpp) and run (rutting/run.hpp).
#include <vrut/rutting/materials.hpp>
#include <vrut/rutting/result.hpp>
#include <vrut/rutting/run.hpp>
#include <vrut/rutting/test.hpp>
