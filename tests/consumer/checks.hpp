#pragma once
// The consumer's checks, one file per graph library.

int check_rapidcheck_property();  // main.cpp
int check_boost_graph();          // boost_graph_use.cpp
int check_lemon_graph();          // lemon_graph_use.cpp (C++17)
