// The translation unit whose precompiled header every test executable reuses (tests/CMakeLists.txt):
// GoogleTest, the standard library, nlohmann-json and the geometry and oracle headers most tests
// include, parsed once per build tree instead of once per test file.
