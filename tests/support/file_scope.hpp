// Included before every test file (tests/CMakeLists.txt). The test files are compiled in batches
// (DEPLOYDYN_UNITY_BATCH), several to one object, so each keeps its helpers and tests in
// `namespace DEPLOYDYN_FILE_SCOPE { … }` instead of an anonymous namespace: in a batch, CMake
// defines DEPLOYDYN_FILE_SCOPE as a name unique to the file (UNITY_BUILD_UNIQUE_ID), so two
// files' kStep or phi() never meet; compiled one file per object it is empty, and the namespace
// is the anonymous one.
#pragma once

#ifndef DEPLOYDYN_FILE_SCOPE
#define DEPLOYDYN_FILE_SCOPE
#endif
