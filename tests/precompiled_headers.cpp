// The object library that builds the tests' precompiled header (tests/CMakeLists.txt) needs a
// source file of its own; the header is all it is for.
