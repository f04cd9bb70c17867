#include "Cli.h"

int main(int argc, char** argv) {
    return px::cli::run(argc, argv);
}
