// Placeholder: replaced by the command line once io is in place.
#include <bimrock/analysis/elastic_analysis.hpp>
int main() { return 0; }
