// Closes the region GlslSubsetBegin.h opened.
#pragma GCC diagnostic pop
