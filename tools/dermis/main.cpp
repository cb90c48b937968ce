// dermis: the command-line front end. Each subcommand lives in its own file
// (Command*.cpp) and registers itself in the table below.
#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
    if (argc < 2 || std::strcmp(argv[1], "--help") == 0) {
        std::printf("usage: dermis <command> [options]\n");
        return argc < 2 ? 2 : 0;
    }
    std::fprintf(stderr, "error: unknown command '%s'\n", argv[1]);
    return 2;
}
