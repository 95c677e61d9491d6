// The translation unit that builds the tests' precompiled header (tests/CMakeLists.txt:
// bounce_test_headers); it has no code of its own.
