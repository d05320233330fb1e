<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/xmi-common.xsl - the tool-neutral core of the XMI import.

  Reads:   UML 2.x XMI of any XMI version (2.0, 2.1, 2.4.x, 2.5.x) and any UML
           namespace (Eclipse UML2 http://www.eclipse.org/uml2/N.N.N/UML,
           OMG http://www.omg.org/spec/UML/YYYYMMDD, EA/StarUML
           http://schema.omg.org/spec/UML/2.x); namespaces are matched by
           pattern (fp:is-uml-ns, fp:is-xmi-ns), never by a fixed list.
  Writes:  nothing itself. It provides
           - mode mp:normalise: a copy of the XMI in fixed namespaces
             (UML elements in urn:robomda:import:uml, XMI elements and
             attributes in urn:robomda:import:xmi, xmi:type reduced to the
             UML metaclass name; an xsi:type, as EMF accepts and GenMyModel
             writes, read as xmi:type when there is none), without xmi:Extension / eAnnotations
             blocks, and with x:type on every element whose metaclass is
             known (written or implied: fp:meta), so rules and keys test
             @x:type instead of calling a function. Every later step reads
             this copy, so one set of rules serves every XMI and UML
             version. The common namespaces are looked up in maps
             ($common-xmi-ns, $common-uml-ns: fp:xmi-ns, fp:uml-ns); the
             patterns run only for other URIs;
           - fp:href-types: what each distinct type href says (library,
             name, primitive kind), computed once per document;
           - the keys (every id look-up goes through xsl:key; ids are
             per file: an xmi:id several files of a model use is "FILE#id",
             x:qid of files.xsl, read by fp:id, fp:ref-id and the keys);
           - functions for ids, metaclasses, references, qualified names,
             value specifications, multiplicities, types and comments.
  Params:  none.
  Errors:  none raised here; callers raise the IMP codes listed in
           import.xsl with the facts these functions return.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:map="http://www.w3.org/2005/xpath-functions/map"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:tp="urn:robomda:xslt:template:private"
    xmlns:u="urn:robomda:import:uml"
    xmlns:x="urn:robomda:import:xmi"
    xmlns:pt="urn:robomda:primitive-types"
    exclude-result-prefixes="#all">

  <!-- ===================================================== namespaces -->
  <xsl:variable name="U" as="xs:string" select="'urn:robomda:import:uml'"/>
  <xsl:variable name="X" as="xs:string" select="'urn:robomda:import:xmi'"/>
  <xsl:variable name="XSI" as="xs:string" select="'http://www.w3.org/2001/XMLSchema-instance'"/>

  <!-- UML metamodel namespaces (not profiles such as .../StandardProfile) -->
  <xsl:function name="fp:is-uml-ns" as="xs:boolean">
    <xsl:param name="uri" as="xs:string"/>
    <xsl:sequence select="matches($uri,
        '^https?://(www\.eclipse\.org/uml2/[0-9.]+/UML|(schema|www)\.omg\.org/(spec/)?UML(/[0-9.]+)?)/?$', 'i')"/>
  </xsl:function>

  <!-- XMI namespaces: 2.0 http://www.omg.org/XMI, 2.1
       http://schema.omg.org/spec/XMI/2.1, 2.4+ http://www.omg.org/spec/XMI/YYYYMMDD -->
  <xsl:function name="fp:is-xmi-ns" as="xs:boolean">
    <xsl:param name="uri" as="xs:string"/>
    <xsl:sequence select="matches($uri,
        '^https?://(schema|www)\.omg\.org/(spec/)?XMI(/[0-9.]+)?/?$', 'i')"/>
  </xsl:function>

  <!-- the XMI and UML namespaces of the common tools, looked up in a map
       by the normalisation before any regular expression is run (only
       those that fp:is-xmi-ns / fp:is-uml-ns accept: the patterns above
       stay the definition) -->
  <xsl:variable name="common-xmi-ns" as="map(xs:string, xs:boolean)" select="map:merge((
      'http://www.omg.org/XMI', 'http://schema.omg.org/spec/XMI/2.1',
      'http://www.omg.org/spec/XMI/20100901', 'http://www.omg.org/spec/XMI/20110701',
      'http://www.omg.org/spec/XMI/20131001', 'http://www.omg.org/spec/XMI/20161101'
      )[fp:is-xmi-ns(.)] ! map:entry(., true()))"/>
  <xsl:variable name="common-uml-ns" as="map(xs:string, xs:boolean)" select="map:merge((
      'http://www.eclipse.org/uml2/2.0.0/UML', 'http://www.eclipse.org/uml2/2.1.0/UML',
      'http://www.eclipse.org/uml2/3.0.0/UML', 'http://www.eclipse.org/uml2/4.0.0/UML',
      'http://www.eclipse.org/uml2/5.0.0/UML', 'http://schema.omg.org/spec/UML/2.0',
      'http://schema.omg.org/spec/UML/2.1', 'http://schema.omg.org/spec/UML/2.1.1',
      'http://schema.omg.org/spec/UML/2.2', 'http://www.omg.org/spec/UML/20090901',
      'http://www.omg.org/spec/UML/20110701', 'http://www.omg.org/spec/UML/20131001',
      'http://www.omg.org/spec/UML/20161101'
      )[fp:is-uml-ns(.)] ! map:entry(., true()))"/>

  <!-- fp:is-xmi-ns and fp:is-uml-ns, the common namespaces first -->
  <xsl:function name="fp:xmi-ns" as="xs:boolean">
    <xsl:param name="uri" as="xs:string"/>
    <xsl:sequence select="map:contains($common-xmi-ns, $uri) or fp:is-xmi-ns($uri)"/>
  </xsl:function>

  <xsl:function name="fp:uml-ns" as="xs:boolean">
    <xsl:param name="uri" as="xs:string"/>
    <xsl:sequence select="map:contains($common-uml-ns, $uri) or fp:is-uml-ns($uri)"/>
  </xsl:function>

  <!-- ================================================== normalisation -->
  <!-- Every element whose UML metaclass is known gets x:type (xmi:type
       reduced to the metaclass name, else the element name of a UML
       element, else the default type of the feature in $default-metas), so
       fp:meta and the match patterns read one attribute. Elements in no
       namespace (most of a file) have their own rule, matched by a name
       test; the attributes in no namespace are copied in one go; the
       namespace patterns run only for URIs outside $common-xmi-ns /
       $common-uml-ns. -->
  <xsl:mode name="mp:normalise" on-no-match="shallow-copy"/>
  <!-- hook for dialect modules: extra attributes on a normalised element
       that has an href (a reference into another file: the only elements
       a dialect annotates; testing @href first spares a template dispatch
       per element) -->
  <xsl:mode name="mp:normalise-extra" on-no-match="deep-skip"/>

  <!-- elements in no namespace (most of an XMI file) -->
  <xsl:template match="Q{}*" mode="mp:normalise" priority="2" as="element()">
    <xsl:copy copy-namespaces="no">
      <xsl:call-template name="tp:normalise-attributes"/>
      <!-- x:type of an element without xmi:type: the declared type of its
           feature -->
      <xsl:variable name="meta" as="xs:string?" select="$default-metas(local-name())"/>
      <xsl:if test="exists($meta) and not(@*:type[namespace-uri()][fp:type-ns(namespace-uri())])">
        <xsl:attribute name="x:type" select="$meta"/>
      </xsl:if>
      <xsl:if test="@href">
        <xsl:apply-templates select="." mode="mp:normalise-extra"/>
      </xsl:if>
      <xsl:apply-templates select="node()" mode="mp:normalise"/>
    </xsl:copy>
  </xsl:template>

  <!-- the placeholders of a template: the element a template parameter
       owns (ownedParameteredElement, ownedDefault) and the actual a
       template binding owns (ownedActual). They are no element of the
       user's model (Papyrus writes a Class "TemplateParameter1" for each
       parameter): x:type TemplateParameter, so no rule imports one as a
       classifier and a type reference to one names it (type-metaclass),
       never a class of the application. -->
  <xsl:template match="ownedParameteredElement | ownedDefault | ownedActual" mode="mp:normalise" priority="3"
                as="element()">
    <xsl:copy copy-namespaces="no">
      <xsl:call-template name="tp:normalise-attributes"/>
      <xsl:attribute name="x:type" select="'TemplateParameter'"/>
      <xsl:apply-templates select="node()" mode="mp:normalise"/>
    </xsl:copy>
  </xsl:template>

  <!-- any other element: by its namespace -->
  <xsl:template match="*" mode="mp:normalise" as="element()">
    <xsl:variable name="ns" as="xs:string" select="namespace-uri()"/>
    <xsl:choose>
      <xsl:when test="fp:uml-ns($ns)">
        <xsl:element name="u:{local-name()}" namespace="{$U}">
          <xsl:call-template name="tp:normalise-attributes"/>
          <xsl:if test="not(@*:type[fp:type-ns(namespace-uri())])">
            <xsl:attribute name="x:type" namespace="{$X}" select="local-name()"/>
          </xsl:if>
          <xsl:if test="@href">
            <xsl:apply-templates select="." mode="mp:normalise-extra"/>
          </xsl:if>
          <xsl:apply-templates select="node()" mode="mp:normalise"/>
        </xsl:element>
      </xsl:when>
      <xsl:when test="fp:xmi-ns($ns)">
        <xsl:element name="x:{local-name()}" namespace="{$X}">
          <xsl:call-template name="tp:normalise-attributes"/>
          <xsl:apply-templates select="node()" mode="mp:normalise"/>
        </xsl:element>
      </xsl:when>
      <xsl:otherwise>
        <xsl:element name="{name()}" namespace="{$ns}">
          <xsl:call-template name="tp:normalise-attributes"/>
          <xsl:if test="$ns eq $U and not(@*:type[fp:type-ns(namespace-uri())])">
            <xsl:attribute name="x:type" namespace="{$X}" select="local-name()"/>
          </xsl:if>
          <xsl:if test="@href">
            <xsl:apply-templates select="." mode="mp:normalise-extra"/>
          </xsl:if>
          <xsl:apply-templates select="node()" mode="mp:normalise"/>
        </xsl:element>
      </xsl:otherwise>
    </xsl:choose>
  </xsl:template>

  <!-- tool extension blocks carry no UML semantics: dropped -->
  <xsl:template match="*:Extension[fp:is-xmi-ns(namespace-uri())] | Q{}eAnnotations" mode="mp:normalise"
                priority="3" as="empty-sequence()"/>
  <xsl:template match="comment() | processing-instruction()" mode="mp:normalise"
                as="empty-sequence()"/>
  <!-- the line breaks and indentation between elements: no rule reads
       them, and they were as many nodes as the elements, in the copy every
       rule reads (issue 35: the import's memory and time). A text that is
       all the content of its element (a comment's body) stays. -->
  <xsl:template match="text()[not(normalize-space())][../*]" mode="mp:normalise"
                as="empty-sequence()"/>

  <!-- the attributes of the context element: those in no namespace (most
       of them) copied in one go, XMI ones into x: (xmi:id and xmi:type,
       nearly every XMI attribute, with a fixed name: cheaper than a
       computed one), any other as it is -->
  <xsl:template name="tp:normalise-attributes" as="attribute()*">
    <xsl:copy-of select="@Q{}*"/>
    <xsl:for-each select="@*[namespace-uri()]">
      <xsl:choose>
        <xsl:when test="fp:xmi-ns(namespace-uri())">
          <xsl:variable name="name" as="xs:string" select="local-name()"/>
          <xsl:choose>
            <xsl:when test="$name eq 'id'">
              <xsl:attribute name="x:id" select="string(.)"/>
            </xsl:when>
            <xsl:when test="$name eq 'type'">
              <xsl:attribute name="x:type" select="fp:norm-type(.)"/>
            </xsl:when>
            <xsl:otherwise>
              <xsl:attribute name="x:{$name}" namespace="{$X}" select="string(.)"/>
            </xsl:otherwise>
          </xsl:choose>
        </xsl:when>
        <!-- xsi:type (EMF accepts it, GenMyModel writes it): the
             metaclass as xmi:type gives it, unless xmi:type is there too -->
        <xsl:when test="local-name() eq 'type' and namespace-uri() eq $XSI
                        and not(../@*:type[fp:xmi-ns(namespace-uri())])">
          <xsl:attribute name="x:type" select="fp:norm-type(.)"/>
        </xsl:when>
        <xsl:otherwise>
          <xsl:copy-of select="."/>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each>
  </xsl:template>

  <!-- a namespace whose "type" attribute gives an element's metaclass:
       XMI's (xmi:type) or XML Schema instance's (xsi:type) -->
  <xsl:function name="fp:type-ns" as="xs:boolean">
    <xsl:param name="uri" as="xs:string"/>
    <xsl:sequence select="$uri eq $XSI or fp:xmi-ns($uri)"/>
  </xsl:function>

  <!-- xmi:type="uml:Class" -> "Class"; a non-UML type -> "{uri}local".
       The UML namespace is looked up first, the pattern runs only for
       other URIs; the common one-colon value is cut with substring-after. -->
  <xsl:function name="fp:norm-type" as="xs:string">
    <xsl:param name="attribute" as="attribute()"/>
    <xsl:variable name="value" as="xs:string" select="normalize-space($attribute)"/>
    <xsl:variable name="prefix" as="xs:string" select="substring-before($value, ':')"/>
    <xsl:variable name="local" as="xs:string" select="substring-after($value, ':')"/>
    <xsl:variable name="uri" as="xs:string"
        select="if ($prefix) then string(namespace-uri-for-prefix($prefix, $attribute/..)) else ''"/>
    <xsl:sequence select="if (not(contains($value, ':'))) then $value
                          else if (fp:uml-ns($uri))
                          then (if (contains($local, ':')) then replace($value, '^.*:', '') else $local)
                          else '{' || $uri || '}' || $local"/>
  </xsl:function>

  <!-- ================================================================ keys -->
  <!-- by the id that identifies an element in the model: its xmi:id, or
       "FILE#id" (x:qid) when several files of the model use that xmi:id
       (files.xsl) -->
  <xsl:key name="fp:by-id" match="*[@x:id]" use="string((@x:qid, @x:id)[1])"/>
  <!-- the elements whose xmi:id several files use, by that xmi:id -->
  <xsl:key name="fp:shared-id" match="*[@x:qid]" use="string(@x:id)"/>

  <xsl:variable name="dependency-metas" as="xs:string+"
      select="('Usage', 'InterfaceRealization', 'Realization', 'ComponentRealization',
               'Deployment', 'Manifestation')"/>

  <xsl:key name="fp:dep-by-client" match="*[@client or client][@x:type = $dependency-metas]"
      use="fp:ref-ids(., 'client')"/>
  <xsl:key name="fp:dep-by-supplier" match="*[@supplier or supplier][@x:type = $dependency-metas]"
      use="fp:ref-ids(., 'supplier')"/>
  <xsl:key name="fp:comment-by-annotated" match="ownedComment"
      use="fp:ref-ids(., 'annotatedElement')"/>
  <!-- stereotype applications: top-level elements outside the UML and XMI
       namespaces that point at model elements with base_* attributes -->
  <xsl:key name="fp:stereotype-by-base"
      match="/x:XMI/*[not(namespace-uri() = ($U, $X))][@*[starts-with(local-name(), 'base_')]]"
      use="fp:base-ids(.)"/>
  <!-- every id either key above holds (and maybe a few more): one look-up
       tells tp:decoration that an element has no stereotype and no
       annotating comment, most elements of a model -->
  <xsl:key name="fp:decorated"
      match="/x:XMI/*[not(namespace-uri() = ($U, $X))][@*[starts-with(local-name(), 'base_')]] | ownedComment"
      use="fp:ref-ids(., 'annotatedElement'), fp:base-ids(.)"/>

  <!-- the ids of the elements stereotype application $app extends (its
       base_* attributes), each as fp:ref-id makes it -->
  <xsl:function name="fp:base-ids" as="xs:string*">
    <xsl:param name="app" as="element()"/>
    <xsl:sequence select="$app/@*[starts-with(local-name(), 'base_')]/tokenize(.) ! fp:ref-id($app, .)"/>
  </xsl:function>

  <!-- the UML model element of a normalised document (a bare uml:Model or
       uml:Package, else the first uml:Model, else uml:Package, of xmi:XMI) -->
  <xsl:key name="fp:model" match="/u:Model | /u:Package | /u:Profile
                                 | /x:XMI/u:Model | /x:XMI/u:Package | /x:XMI/u:Profile"
      use="'model'"/>

  <xsl:function name="fp:model-el" as="element()?">
    <xsl:param name="name" as="node()"/>
    <xsl:variable name="models" as="element()*" select="key('fp:model', 'model', root($name))"/>
    <xsl:sequence select="($models[self::u:Model], $models[self::u:Package], $models)[1]"/>
  </xsl:function>

  <!-- =================================================== ids, metaclass -->
  <!-- the element's xmi:id ("FILE#id" when several files of the model use
       it: x:qid, files.xsl), or a deterministic synthetic id
       "robomda.<path>" anchored at the nearest ancestor that has an xmi:id -->
  <xsl:function name="fp:id" as="xs:string">
    <xsl:param name="element" as="element()"/>
    <xsl:variable name="written" as="attribute()?" select="($element/@x:qid, $element/@x:id)[1]"/>
    <xsl:sequence select="if ($written) then string($written) else fp:synthetic-id($element)"/>
  </xsl:function>

  <xsl:function name="fp:synthetic-id" as="xs:string">
    <xsl:param name="element" as="element()"/>
    <xsl:variable name="anchor" as="element()?" select="$element/ancestor::*[@x:id][1]"/>
    <xsl:variable name="steps" as="element()*"
        select="$element/ancestor-or-self::*[empty($anchor) or . >> $anchor]"/>
    <xsl:sequence select="string-join(('robomda', $anchor ! fp:id(.),
                                       $steps ! fp:step(.)), '.')"/>
  </xsl:function>

  <!-- an element's siblings of its name (itself among them), in document
       order: a look-up per step, not a scan of the siblings per element -->
  <xsl:key name="fp:same-name-siblings" match="*" use="fp:sibling-key(.)"/>

  <xsl:function name="fp:sibling-key" as="xs:string">
    <xsl:param name="element" as="element()"/>
    <xsl:sequence select="generate-id($element/..) || '|' || namespace-uri($element) || '|' || local-name($element)"/>
  </xsl:function>

  <xsl:function name="fp:step" as="xs:string">
    <xsl:param name="text" as="element()"/>
    <xsl:variable name="name" as="xs:string"
        select="if (namespace-uri($text) = ($U, $X)) then local-name($text) else replace(name($text), ':', '-')"/>
    <xsl:variable name="same" as="element()*"
        select="if (root($text) instance of document-node()) then key('fp:same-name-siblings', fp:sibling-key($text), root($text))
                else $text/../*[node-name(.) eq node-name($text)]"/>
    <xsl:sequence select="if (count($same) gt 1) then $name || '-' || fp:place($same, $text, 1, count($same)) else $name"/>
  </xsl:function>

  <!-- the position of $node in $nodes (distinct, in document order), looked
       for between $low and $high by halving -->
  <xsl:function name="fp:place" as="xs:integer">
    <xsl:param name="nodes" as="node()+"/>
    <xsl:param name="node" as="node()"/>
    <xsl:param name="low" as="xs:integer"/>
    <xsl:param name="high" as="xs:integer"/>
    <xsl:variable name="middle" as="xs:integer" select="($low + $high) idiv 2"/>
    <xsl:sequence select="if ($low ge $high) then $low
                          else if ($nodes[$middle] &lt;&lt; $node) then fp:place($nodes, $node, $middle + 1, $high)
                          else fp:place($nodes, $node, $low, $middle)"/>
  </xsl:function>

  <!-- a derived id for the n-th (n > 1) PIM element made from one XMI element -->
  <xsl:function name="fp:nth-id" as="xs:string">
    <xsl:param name="element" as="element()"/>
    <xsl:param name="name" as="xs:integer"/>
    <xsl:sequence select="if ($name eq 1) then fp:id($element) else 'robomda.' || fp:id($element) || '.' || $name"/>
  </xsl:function>

  <!-- the id of the PIM element made for one pair of a relationship with
       several clients or suppliers (UML Designer: client="class port
       component"): $rel's ids are numbered in blocks of $count, one block
       per id of $sides (the relationship's ids at the end where $side is:
       its clients, say), in their order; $n is the pair's place in
       $side's block. The first pair keeps $rel's own id, each other one
       gets a deterministic id of its own (fp:nth-id). A $side that is not
       among $sides (an interfaceRealization owned by its client, which
       it does not name) takes the first block. -->
  <xsl:function name="fp:pair-id" as="xs:string">
    <xsl:param name="rel" as="element()"/>
    <xsl:param name="sides" as="xs:string*"/>
    <xsl:param name="side" as="xs:string"/>
    <xsl:param name="count" as="xs:integer"/>
    <xsl:param name="n" as="xs:integer"/>
    <xsl:sequence select="fp:nth-id($rel, (max((index-of(distinct-values($sides), $side)[1], 1)) - 1) * $count + $n)"/>
  </xsl:function>

  <!-- the UML metaclass: xmi:type, else the element name (root uml:Model),
       else the type XMI lets a tool omit: the declared type of the feature -->
  <xsl:variable name="default-metas" as="map(xs:string, xs:string)" select="map {
      'ownedAttribute': 'Property', 'ownedEnd': 'Property', 'ownedOperation': 'Operation',
      'ownedParameter': 'Parameter', 'generalization': 'Generalization',
      'interfaceRealization': 'InterfaceRealization', 'realization': 'ComponentRealization',
      'deployment': 'Deployment', 'manifestation': 'Manifestation',
      'ownedConnector': 'Connector', 'end': 'ConnectorEnd', 'nestedNode': 'Node',
      'nestedArtifact': 'Artifact', 'ownedComment': 'Comment',
      'ownedLiteral': 'EnumerationLiteral', 'ownedPort': 'Port' }"/>

  <xsl:function name="fp:meta" as="xs:string">
    <xsl:param name="element" as="element()"/>
    <xsl:sequence select="
        if ($element/@x:type) then string($element/@x:type)
        else if (namespace-uri($element) eq $U) then local-name($element)
        else if (namespace-uri($element) eq '') then (map:get($default-metas, local-name($element)), '')[1]
        else ''"/>
  </xsl:function>

  <xsl:variable name="node-metas" as="xs:string+" select="('Node', 'Device', 'ExecutionEnvironment')"/>
  <xsl:variable name="artifact-metas" as="xs:string+" select="('Artifact', 'DeploymentSpecification')"/>
  <xsl:variable name="platform-metas" as="xs:string+"
      select="($node-metas, $artifact-metas, 'CommunicationPath')"/>

  <!-- ===================================================== references -->
  <!-- ids referenced by property $prop: an attribute (an id list) or child
       elements with xmi:idref; each as fp:ref-id makes it -->
  <xsl:function name="fp:ref-ids" as="xs:string*">
    <xsl:param name="element" as="element()"/>
    <xsl:param name="prop" as="xs:string"/>
    <xsl:sequence select="($element/@Q{}*[local-name() eq $prop]/tokenize(.),
                           $element/Q{}*[local-name() eq $prop]/@x:idref/string()) ! fp:ref-id($element, .)"/>
  </xsl:function>

  <!-- the id that identifies the element a reference $id written in the
       file of $ctx names (the key of fp:by-id, the fp:id of that element):
       $id itself, unless several files of the model use that xmi:id
       (files.xsl): then "FILE#id", FILE the file of $ctx (ids are per file) -->
  <xsl:function name="fp:ref-id" as="xs:string">
    <xsl:param name="ctx" as="node()"/>
    <xsl:param name="id" as="xs:string"/>
    <xsl:sequence select="if (empty(key('fp:shared-id', $id, root($ctx)))) then $id
                          else string($ctx/ancestor-or-self::*[@x:file][1]/@x:file) || '#' || $id"/>
  </xsl:function>

  <!-- the element with xmi:id $id (a reference written in the file of
       $ctx: fp:ref-id) in the document of $ctx -->
  <xsl:function name="fp:element" as="element()?">
    <xsl:param name="ctx" as="node()"/>
    <xsl:param name="id" as="xs:string?"/>
    <xsl:sequence select="if ($id) then key('fp:by-id', fp:ref-id($ctx, $id), root($ctx))[1] else ()"/>
  </xsl:function>

  <!-- the local elements referenced by property $prop (hrefs and unknown
       ids dropped: the check pass reports unknown ids first) -->
  <xsl:function name="fp:targets" as="element()*">
    <xsl:param name="element" as="element()"/>
    <xsl:param name="prop" as="xs:string"/>
    <xsl:sequence select="fp:ref-ids($element, $prop) ! fp:element($element, .)"/>
  </xsl:function>

  <!-- the ids among $ids (fp:ref-ids: the references inside the file;
       hrefs are never dangling) that are neither in the file nor a tool
       built-in -->
  <xsl:function name="fp:dangling-ids" as="xs:string*">
    <xsl:param name="ctx" as="node()"/>
    <xsl:param name="ids" as="xs:string*"/>
    <xsl:sequence select="$ids[empty(fp:element($ctx, .))][empty(fp:builtin-library(.))]"/>
  </xsl:function>

  <!-- ================================================ qualified names -->
  <!-- "root::pkg::Class::attr": the names from the model root (fp:model-
       root, found once per document and passed down) to $e -->
  <xsl:function name="fp:qname" as="xs:string">
    <xsl:param name="element" as="element()"/>
    <xsl:param name="root" as="element()"/>
    <xsl:sequence select="string-join($element/ancestor-or-self::*[not(. &lt;&lt; $root)] ! string(@name), '::')"/>
  </xsl:function>

  <xsl:function name="fp:label" as="xs:string">
    <xsl:param name="element" as="element()"/>
    <xsl:sequence select="(fp:meta($element)[.], local-name($element))[1] ||
                          (if ($element/@name) then ' ''' || $element/@name || '''' else '')"/>
  </xsl:function>

  <!-- ================================================ value specifications -->
  <!-- the value of a ValueSpecification as written in the model -->
  <xsl:function name="fp:value" as="xs:string?">
    <xsl:param name="value-item" as="element()?"/>
    <xsl:variable name="meta" as="xs:string" select="if ($value-item) then fp:meta($value-item) else ''"/>
    <xsl:variable name="value" as="xs:string?"
        select="($value-item/@value, $value-item/value[not(@xsi:nil = 'true')])[1]/string()"
        xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"/>
    <xsl:sequence select="
        if (empty($value-item)) then ()
        else if ($meta = ('LiteralInteger', 'LiteralUnlimitedNatural', 'LiteralReal'))
          then ($value, '0')[1]
        else if ($meta eq 'LiteralBoolean') then ($value, 'false')[1]
        else if ($meta eq 'LiteralNull') then ()
        else if ($meta = ('OpaqueExpression', 'TimeExpression', 'Duration'))
          then ($value-item/@body, $value-item/body, $value-item/expr/@body)[1]/string()
        else if ($meta eq 'Expression') then ($value-item/@symbol/string(), $value)[1]
        else if ($meta eq 'InstanceValue')
          then (fp:targets($value-item, 'instance')/@name/string(), $value-item/@name/string(), $value)[1]
        else $value"/>
  </xsl:function>

  <!-- a multiplicity bound: the value of $spec (lowerValue, upperValue),
       else the attribute $attr (lower, upper); "*" for unlimited -->
  <xsl:function name="fp:bound" as="xs:string?">
    <xsl:param name="spec" as="element()?"/>
    <xsl:param name="attr" as="attribute()*"/>
    <xsl:variable name="raw" as="xs:string?"
        select="if ($spec) then fp:value($spec) else $attr/string()"/>
    <xsl:sequence select="if ($raw = ('-1', '*')) then '*' else $raw"/>
  </xsl:function>

  <!-- the default value of a Property or Parameter, absent when none -->
  <xsl:function name="fp:default" as="xs:string?">
    <xsl:param name="element" as="element()"/>
    <xsl:sequence select="if ($element/defaultValue) then fp:value($element/defaultValue[1])
                          else $element/@default/string()"/>
  </xsl:function>

  <!-- ============================================================ types -->
  <xsl:variable name="primitive-table" as="document-node()"
      select="doc('../common/primitive-types.xml')"/>
  <xsl:key name="fp:primitive" match="pt:type" use="../@name || '|' || @name"/>

  <xsl:function name="fp:primitive-kind" as="xs:string?">
    <xsl:param name="library" as="xs:string"/>
    <xsl:param name="name" as="xs:string?"/>
    <xsl:sequence select="if (not($name)) then ()
        else (key('fp:primitive', $library || '|' || $name, $primitive-table),
              key('fp:primitive', 'generic|' || lower-case(normalize-space($name)), $primitive-table)
             )[1]/@kind/string()"/>
  </xsl:function>

  <!-- the library of an href, by the patterns of the table; else external -->
  <xsl:function name="fp:href-library" as="xs:string">
    <xsl:param name="href" as="xs:string"/>
    <xsl:variable name="doc" as="xs:string" select="replace($href, '#.*$', '')"/>
    <xsl:sequence select="($primitive-table/pt:primitive-types/pt:library
                           [pt:href[matches($doc, @pattern, 'i')]][1]/@name/string(), 'external')[1]"/>
  </xsl:function>

  <!-- the library of a tool built-in type id (EAJava_int), if it is one -->
  <xsl:function name="fp:builtin-library" as="xs:string?">
    <xsl:param name="id" as="xs:string"/>
    <xsl:sequence select="$primitive-table/pt:primitive-types/pt:library
                          [pt:tool-id[starts-with($id, @prefix)]][1]/@name/string()"/>
  </xsl:function>

  <xsl:function name="fp:builtin-name" as="xs:string">
    <xsl:param name="id" as="xs:string"/>
    <xsl:variable name="prefix" as="xs:string"
        select="($primitive-table//pt:tool-id[starts-with($id, @prefix)])[1]/@prefix"/>
    <xsl:sequence select="substring($id, string-length($prefix) + 1)"/>
  </xsl:function>

  <!-- the name of a type referenced by href: the dialect's name for it
       (mp:normalise-extra, x:referent-path), else the last step of the
       readable path of an RSA fragment ("#id?Path/Name?"), else the
       fragment's last step, else the last path step of the document;
       URL-decoded -->
  <xsl:function name="fp:href-name" as="xs:string">
    <xsl:param name="href" as="xs:string"/>
    <xsl:param name="el" as="element()?"/>
    <xsl:variable name="fragment" as="xs:string" select="substring-after($href, '#')"/>
    <xsl:variable name="path" as="xs:string" select="replace(substring-after($fragment, '?'), '\?$', '')"/>
    <xsl:sequence select="
        if ($el/@x:referent-path) then tokenize($el/@x:referent-path, '::')[last()]
        else if ($path) then fp:uri-decode(tokenize(replace($path, '/+$', ''), '/')[last()])
        else if ($fragment) then fp:uri-decode(tokenize(replace($fragment, '/+$', ''), '/')[last()])
        else fp:uri-decode(replace(tokenize(replace($href, '/+$', ''), '/')[last()], '\.[^.]*$', ''))"/>
  </xsl:function>

  <!-- $text with its %XX escapes (UTF-8 bytes) decoded; a run of escapes
       that is not UTF-8 is kept as written -->
  <xsl:function name="fp:uri-decode" as="xs:string">
    <xsl:param name="text" as="xs:string"/>
    <xsl:sequence select="if (not(contains($text, '%'))) then $text
        else string-join(analyze-string($text, '(%[0-9A-Fa-f]{2})+')/*
            ! (if (self::fn:match) then fp:utf8(tokenize(substring(., 2), '%') ! fp:hex(.), string(.)) else string(.)))"
        xmlns:fn="http://www.w3.org/2005/xpath-functions"/>
  </xsl:function>

  <!-- the number two hex digits write -->
  <xsl:function name="fp:hex" as="xs:integer">
    <xsl:param name="digits" as="xs:string"/>
    <xsl:sequence select="16 * string-length(substring-before('0123456789abcdef', lower-case(substring($digits, 1, 1))))
                          + string-length(substring-before('0123456789abcdef', lower-case(substring($digits, 2, 1))))"/>
  </xsl:function>

  <!-- the characters UTF-8 bytes $bytes encode, else $raw -->
  <xsl:function name="fp:utf8" as="xs:string">
    <xsl:param name="bytes" as="xs:integer*"/>
    <xsl:param name="raw" as="xs:string"/>
    <xsl:variable name="codes" as="xs:integer*" select="fp:utf8-codes($bytes)"/>
    <xsl:sequence select="if (some $c in $codes satisfies $c lt 0) then $raw else codepoints-to-string($codes)"/>
  </xsl:function>

  <!-- the code points of UTF-8 bytes $bytes; -1 where they are not UTF-8 -->
  <xsl:function name="fp:utf8-codes" as="xs:integer*">
    <xsl:param name="bytes" as="xs:integer*"/>
    <xsl:variable name="b" as="xs:integer?" select="head($bytes)"/>
    <xsl:variable name="n" as="xs:integer"
        select="if (empty($b)) then 0 else if ($b lt 128) then 1 else if ($b lt 194) then -1
                else if ($b lt 224) then 2 else if ($b lt 240) then 3 else if ($b lt 245) then 4 else -1"/>
    <xsl:variable name="tail" as="xs:integer*" select="subsequence($bytes, 2, $n - 1)"/>
    <xsl:sequence select="
        if (empty($b)) then ()
        else if ($n lt 0 or count($tail) ne $n - 1 or (some $t in $tail satisfies ($t lt 128 or $t ge 192))) then -1
        else if ($n eq 1) then ($b, fp:utf8-codes(tail($bytes)))
        else (fp:fold-bits($b - (if ($n eq 2) then 192 else if ($n eq 3) then 224 else 240), $tail),
              fp:utf8-codes(subsequence($bytes, $n + 1)))"/>
  </xsl:function>

  <xsl:function name="fp:fold-bits" as="xs:integer">
    <xsl:param name="acc" as="xs:integer"/>
    <xsl:param name="tail" as="xs:integer*"/>
    <xsl:sequence select="if (empty($tail)) then $acc else fp:fold-bits($acc * 64 + head($tail) - 128, tail($tail))"/>
  </xsl:function>

  <!-- a local type that robomda may treat as a primitive: a PrimitiveType,
       or a DataType without attributes (StarUML writes int, string ... so) -->
  <xsl:function name="fp:is-primitive-like" as="xs:boolean">
    <xsl:param name="type" as="element()"/>
    <xsl:variable name="meta" as="xs:string" select="fp:meta($type)"/>
    <xsl:sequence select="$meta eq 'PrimitiveType'
                          or ($meta eq 'DataType' and empty($type/ownedAttribute))"/>
  </xsl:function>

  <!-- what an href says about a type: map { 'library': fp:href-library,
       'name': the library's name rule's (primitive-types.xml: a ROS message
       of Papyrus for Robotics' library is package/Name), else fp:href-name
       without a dialect name, 'kind': fp:primitive-kind
       of the two }. The same few hrefs repeat thousands of times, so
       fp:href-types computes this once per distinct href of a document and
       fp:typed looks it up. -->
  <xsl:function name="fp:href-type" as="map(*)">
    <xsl:param name="href" as="xs:string"/>
    <xsl:variable name="lib" as="xs:string" select="fp:href-library($href)"/>
    <xsl:variable name="rule" as="element(pt:name)?"
        select="$primitive-table/pt:primitive-types/pt:library[@name eq $lib]/pt:name[matches($href, @pattern)][1]"/>
    <xsl:variable name="name" as="xs:string"
        select="if ($rule) then replace($href, $rule/@pattern, $rule/@replacement) else fp:href-name($href, ())"/>
    <!-- a library that names its types by id only says the type's name (@label) -->
    <xsl:variable name="label" as="xs:string?" select="key('fp:primitive', $lib || '|' || $name, $primitive-table)/@label"/>
    <xsl:sequence select="map { 'library': $lib, 'name': ($label, $name)[1], 'kind': fp:primitive-kind($lib, $name) }"/>
  </xsl:function>

  <!-- fp:href-type of every distinct href of a type reference in $norm -->
  <xsl:function name="fp:href-types" as="map(*)">
    <xsl:param name="norm" as="document-node()"/>
    <xsl:sequence select="map:merge(distinct-values($norm//type/@href) ! map { string(.): fp:href-type(.) })"/>
  </xsl:function>

  <!-- the pim:typed attributes (type, type-name, type-library, primitive,
       lower, upper) of a typed element; lower and upper are always written,
       1 when the model leaves them unset (the UML default). $href-types:
       fp:href-types of the document (an href missing there is computed) -->
  <xsl:function name="fp:typed" as="attribute()*">
    <xsl:param name="element" as="element()"/>
    <xsl:param name="href-types" as="map(*)"/>
    <!-- the first type reference: an id of the type attribute, else the
         first type child with an xmi:idref (an id) or an href -->
    <xsl:variable name="attr-id" as="xs:string?" select="tokenize($element/@type)[1]"/>
    <xsl:variable name="child" as="element()?"
        select="if (exists($attr-id)) then () else $element/type[@x:idref or @href][1]"/>
    <xsl:variable name="id" as="xs:string?"
        select="if (exists($attr-id)) then $attr-id else $child/@x:idref/string()"/>
    <xsl:variable name="href" as="xs:string?" select="if (exists($id)) then () else $child/@href/string()"/>
    <xsl:variable name="type-item" as="element()?" select="if (exists($id)) then fp:element($element, $id) else ()"/>
    <xsl:choose>
      <xsl:when test="empty($id) and empty($href)"/>
      <xsl:when test="exists($href)">
        <xsl:variable name="info" as="map(*)" select="($href-types($href), fp:href-type($href))[1]"/>
        <xsl:variable name="lib" as="xs:string" select="$info?library"/>
        <xsl:variable name="dialect-name" as="xs:boolean" select="exists($child/@x:referent-path)"/>
        <xsl:variable name="name" as="xs:string"
            select="if ($dialect-name) then fp:href-name($href, $child) else $info?name"/>
        <xsl:attribute name="type-name" select="$name"/>
        <xsl:attribute name="type-library" select="$lib"/>
        <xsl:for-each select="if ($dialect-name) then fp:primitive-kind($lib, $name) else $info?kind">
          <xsl:attribute name="primitive" select="."/>
        </xsl:for-each>
      </xsl:when>
      <xsl:when test="exists($type-item) and not($type-item/@x:type = $type-metas)">
        <!-- an element of the model that the PIM holds under no id of
             its own (a behaviour, a collaboration, an association ...):
             named, never a reference that would dangle -->
        <xsl:attribute name="type-name" select="string($type-item/@name)"/>
        <xsl:attribute name="type-library" select="'local'"/>
        <xsl:attribute name="type-metaclass" select="fp:meta($type-item)"/>
      </xsl:when>
      <xsl:when test="exists($type-item)">
        <xsl:attribute name="type" select="fp:id($type-item)"/>
        <xsl:attribute name="type-name" select="string($type-item/@name)"/>
        <xsl:attribute name="type-library" select="'local'"/>
        <xsl:if test="fp:is-primitive-like($type-item)">
          <xsl:for-each select="fp:primitive-kind('local', $type-item/@name)">
            <xsl:attribute name="primitive" select="."/>
          </xsl:for-each>
        </xsl:if>
      </xsl:when>
      <xsl:when test="exists(fp:builtin-library($id))">
        <xsl:variable name="lib" as="xs:string" select="fp:builtin-library($id)"/>
        <xsl:variable name="name" as="xs:string" select="fp:builtin-name($id)"/>
        <xsl:attribute name="type-name" select="$name"/>
        <xsl:attribute name="type-library" select="$lib"/>
        <xsl:for-each select="fp:primitive-kind($lib, $name)">
          <xsl:attribute name="primitive" select="."/>
        </xsl:for-each>
      </xsl:when>
    </xsl:choose>
    <!-- always explicit: tools differ in writing the default 1..1 or not -->
    <xsl:attribute name="lower" select="(fp:bound($element/*:lowerValue[1], $element/@*:lower), '1')[1]"/>
    <xsl:attribute name="upper" select="(fp:bound($element/*:upperValue[1], $element/@*:upper), '1')[1]"/>
  </xsl:function>

  <!-- the metaclasses of the local types a PIM element stands for (the
       PIM holds them with their xmi:id) -->
  <xsl:variable name="type-metas" as="xs:string+"
      select="('PrimitiveType', 'DataType', 'Signal', 'Enumeration', 'Class', 'Interface', 'Component',
               $node-metas, $artifact-metas)"/>
  <!-- behaviours: an attribute typed by one is a function of its owner -->
  <xsl:variable name="behavior-metas" as="xs:string+"
      select="('OpaqueBehavior', 'FunctionBehavior', 'Activity', 'StateMachine', 'ProtocolStateMachine',
               'Interaction')"/>

  <!-- the local type element of a typed element, if any -->
  <xsl:function name="fp:type-element" as="element()?">
    <xsl:param name="element" as="element()"/>
    <xsl:sequence select="fp:targets($element, 'type')[1]"/>
  </xsl:function>

  <!-- ========================================================= comments -->
  <!-- the documentation of an element: bodies of the comments annotating
       it, and of the comments it owns that annotate nothing -->
  <xsl:function name="fp:doc" as="xs:string?">
    <xsl:param name="element" as="element()"/>
    <xsl:variable name="comments" as="element()*"
        select="key('fp:comment-by-annotated', fp:id($element), root($element))
                | $element/ownedComment[empty(fp:ref-ids(., 'annotatedElement'))]"/>
    <xsl:variable name="bodies" as="xs:string*"
        select="$comments ! string((@body, body)[1])[normalize-space()]"/>
    <xsl:sequence select="if (exists($bodies)) then string-join($bodies, '&#10;&#10;') else ()"/>
  </xsl:function>

  <!-- ========================================================= booleans -->
  <xsl:function name="fp:bool" as="xs:string">
    <xsl:param name="attribute" as="attribute()?"/>
    <xsl:param name="default" as="xs:boolean"/>
    <xsl:sequence select="if (empty($attribute)) then string($default)
                          else string(normalize-space(lower-case($attribute)) = ('true', '1'))"/>
  </xsl:function>

  <xsl:function name="fp:visibility" as="xs:string">
    <xsl:param name="element" as="element()"/>
    <xsl:variable name="value" as="xs:string" select="lower-case(normalize-space($element/@visibility))"/>
    <xsl:sequence select="if ($value = ('public', 'protected', 'private', 'package')) then $value else 'public'"/>
  </xsl:function>
</xsl:stylesheet>
