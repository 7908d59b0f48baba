// SPDX-License-Identifier: MIT
// Nothing: the program frusta_test_headers (tests/CMakeLists.txt) exists for its
// precompiled header, which every test program reuses.
