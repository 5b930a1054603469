"""Read a results folder into numpy tables, without pandas.

Prints each dataset's descriptors ranked by ROC AUC, and checks the PR-curve area in the summary
against one recomputed with numpy from the descriptor's curve (trapezoids over recall).

    PYTHONPATH=build/python python3 examples/python/read_results.py [results/quickstart]
"""
import pathlib
import sys

import numpy as np

import radarpr


def main(folder):
    results = radarpr.load_results(folder)
    print(f"{results.experiment}: {len(results.datasets)} datasets x "
          f"{len(results.descriptors)} descriptors")
    for dataset in results.datasets:
        table = results.table(dataset)
        order = np.argsort(-np.nan_to_num(table["roc_auc"], nan=-1.0))
        print(f"\n{dataset}")
        print(f"{'descriptor':<32} {'ROC AUC':>8} {'F1-max':>8} {'R@1':>8} {'bytes':>6}")
        for i in order:
            print(f"{table['label'][i]:<32} {table['roc_auc'][i]:8.3f} {table['f1_max'][i]:8.3f} "
                  f"{table['recall_at_1'][i]:8.3f} {int(table['payload_bytes'][i]):6d}")
        for i, descriptor in enumerate(table["descriptor"]):
            curve = results.curve(dataset, descriptor)
            defined = ~np.isnan(curve["precision"])
            recall, precision = curve["recall"][defined], curve["precision"][defined]
            area = float(np.sum(np.diff(recall) * (precision[1:] + precision[:-1]) / 2))
            summary = table["pr_auc_trapezoid"][i]
            if not np.isclose(area, summary, rtol=0, atol=1e-5):
                raise SystemExit(f"{dataset} {descriptor}: PR area {area} from curve.csv, "
                                 f"{summary} in the summary")
    print("\nPR areas recomputed from every curve.csv match the summary (to 1e-5)")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else
         pathlib.Path(__file__).resolve().parents[2] / "results" / "quickstart")
