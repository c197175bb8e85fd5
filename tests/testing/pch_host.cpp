// The source of the targets that host the tests' precompiled headers (tests/CMakeLists.txt): a
// target needs one file to compile; the header itself is what the tests reuse.
