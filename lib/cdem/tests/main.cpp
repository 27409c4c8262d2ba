// main() comes from Catch2::Catch2WithMain, Debian's prebuilt libCatch2WithMain.a:
// Catch's implementation is compiled once, not into each test program.
