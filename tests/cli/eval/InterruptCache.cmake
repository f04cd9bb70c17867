# The interrupted recommendation's cache folder: one file of someone else's in it, and its twin
# beside it to compare with afterwards.
file(REMOVE_RECURSE interrupt-cache)
file(MAKE_DIRECTORY interrupt-cache)
file(WRITE interrupt-cache/notes.txt "not the cache's: left alone\n")
file(WRITE interrupt-notes-twin.txt "not the cache's: left alone\n")
