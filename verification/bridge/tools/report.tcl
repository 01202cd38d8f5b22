proc writeReport {results outDir} {}
