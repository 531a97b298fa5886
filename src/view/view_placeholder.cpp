// Placeholder until the view's server lands (docs/view.md).
#include "view/view_page.hpp"
