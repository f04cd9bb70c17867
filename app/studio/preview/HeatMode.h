#pragma once
// Which of a view's two errors its heat map shows (ErrorStats.h): the technique's own, against
// the exact hit on the height level it reads, or the filtering's, that level against level 0.

namespace px::studio {

enum class HeatMode { Technique, Filtering };

} // namespace px::studio
