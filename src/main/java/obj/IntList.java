package obj;

import java.util.Arrays;

/** A growable int array. */
final class IntList {
    private int[] data = new int[48];
    private int size;

    void add(int value) {
        if (size == data.length) data = Arrays.copyOf(data, DoubleList.grown(size));
        data[size++] = value;
    }

    int get(int i) {
        return data[i];
    }

    int size() {
        return size;
    }

    int capacity() {
        return data.length;
    }

    int[] toArray() {
        return Arrays.copyOf(data, size);
    }
}
