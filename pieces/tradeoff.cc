// tradeoff's main(): vl::tradeoff_main (framework/apps/tradeoff_main.hh) with every piece this build links.
#include <cstdio>
#include <exception>

#include "all_pieces.hh"
#include "tradeoff_main.hh"

int main(int argc, char** argv) {
    vl::registry pieces;
    try {
        vl::register_all_pieces(pieces);
    } catch (const std::exception& e) {  // a piece bound twice, or under a malformed name
        std::fprintf(stderr, "tradeoff: %s\n", e.what());
        return 1;
    }
    return vl::tradeoff_main(argc, argv, pieces);
}
