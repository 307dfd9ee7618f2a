// partet command line (being built up; see README).
#include <cstdio>
int main() { std::puts("partet " PARTET_VERSION); return 0; }
