// Members of Illustrator's scripting DOM that the Scripting Reference documents but the published
// typings (types-for-adobe/Illustrator/2022) omit. Each cites its source; nothing is invented.

interface Document {
  /**
   * Retrieves the page item with this uuid (PageItem.uuid). Added in Illustrator 24.0 (CC 2020):
   * ai-scripting.docsforadobe.dev, Document.getPageItemFromUuid. Throws when no item has the uuid.
   * Optional here because Illustrator 22–23 lack it; the bridge checks before calling.
   */
  getPageItemFromUuid?: (uuid: string) => PageItem
}
