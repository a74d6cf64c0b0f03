#include <iostream>
int main() { std::cerr << "taut: under construction\n"; return 3; }
