#pragma once
// Floats written as text (material files, engine exports) as the shortest decimal that reads back
// to the same float: 0.05f is written "0.05", not "0.05000000074505806".

namespace px {

// The double nearest to the shortest decimal (6 to 9 significant digits) that reads back as
// `value`. Writers that print a double then print that decimal.
double shortestDecimal(float value);

} // namespace px
