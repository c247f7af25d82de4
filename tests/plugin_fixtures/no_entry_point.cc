// A shared library that is no icpbench plugin: it lacks the entry point
// (tests/plugin_test.cc).
extern "C" int not_an_icpbench_plugin() { return 0; }
