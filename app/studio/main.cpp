// parallax-studio: the editor. Everything lives in the studio library (Studio.cpp).
#include "Studio.h"

int main(int argc, char** argv) {
    return px::studio::runStudio(argc, argv);
}
