#pragma once
// eikon::Error is part of the public API (include/eikon/error.h): the library's users catch the
// very type the code inside throws.
#include "eikon/error.h"
