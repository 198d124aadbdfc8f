<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr_FR">
<context>
    <name>inlay::studio::Autosaver</name>
    <message>
        <location filename="../app/studio/autosave.cpp" line="60"/>
        <source>%1: cannot take the lock</source>
        <translation>%1 : impossible de prendre le verrou</translation>
    </message>
    <message>
        <location filename="../app/studio/autosave.cpp" line="102"/>
        <source>%1: cannot write (%2)</source>
        <translation>%1 : écriture impossible (%2)</translation>
    </message>
</context>
<context>
    <name>inlay::studio::Document</name>
    <message>
        <location filename="../app/studio/document.cpp" line="288"/>
        <location filename="../app/studio/document.cpp" line="318"/>
        <source>Preparation was cancelled.</source>
        <translation>La préparation a été annulée.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="374"/>
        <location filename="../app/studio/document.cpp" line="615"/>
        <location filename="../app/studio/document.cpp" line="797"/>
        <location filename="../app/studio/document.cpp" line="854"/>
        <source>The position is not a number.</source>
        <translation>La position n&apos;est pas un nombre.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="376"/>
        <location filename="../app/studio/document.cpp" line="447"/>
        <source>The height must be greater than zero.</source>
        <translation>La hauteur doit être supérieure à zéro.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="398"/>
        <source>Move object %1</source>
        <translation>Déplacer l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="405"/>
        <source>Change height of object %1</source>
        <translation>Changer la hauteur de l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="412"/>
        <source>Turn object %1</source>
        <translation>Tourner l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="419"/>
        <source>Change material of object %1</source>
        <translation>Changer le matériau de l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="434"/>
        <source>There is no object %1.</source>
        <translation>Il n&apos;y a pas d&apos;objet %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="435"/>
        <source>The scene is still being prepared.</source>
        <translation>La scène est encore en préparation.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="436"/>
        <source>The scene could not be prepared.</source>
        <translation>La scène n&apos;a pas pu être préparée.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="458"/>
        <source>Insert object %1</source>
        <translation>Insérer l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="470"/>
        <source>Delete object %1</source>
        <translation>Supprimer l&apos;objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="580"/>
        <source>Open a photo first.</source>
        <translation>Ouvrez d&apos;abord une photo.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="600"/>
        <source>There is no estimated box yet.</source>
        <translation>Il n&apos;y a pas encore de pièce estimée.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="605"/>
        <source>Accept the estimated box</source>
        <translation>Accepter la pièce estimée</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="611"/>
        <source>There is no such corner of the back wall.</source>
        <translation>Ce coin du mur du fond n&apos;existe pas.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="621"/>
        <source>Move a corner of the back wall</source>
        <translation>Déplacer un coin du mur du fond</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="627"/>
        <source>Estimate the box again</source>
        <translation>Estimer à nouveau la pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="632"/>
        <source>A light&apos;s outline needs at least three points around an area.</source>
        <translation>Le contour d&apos;une lampe doit compter au moins trois points entourant une surface.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="640"/>
        <source>Outline light %1</source>
        <translation>Détourer la lampe %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="646"/>
        <location filename="../app/studio/document.cpp" line="817"/>
        <source>Each box of a shaft must be at least two pixels wide and high.</source>
        <translation>Chaque cadre d&apos;un rayon de soleil doit mesurer au moins deux pixels de large et de haut.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="654"/>
        <source>Add shaft %1</source>
        <translation>Ajouter le rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="661"/>
        <source>A surface&apos;s outline needs at least three points around an area.</source>
        <translation>Le contour d&apos;une surface doit compter au moins trois points entourant une aire.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="670"/>
        <source>Add surface %1</source>
        <translation>Ajouter la surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="681"/>
        <source>An occluder needs a stroke over the thing in front and one over what is behind it.</source>
        <translation>Un masque d&apos;avant-plan demande un trait sur ce qui est devant et un sur ce qui est derrière.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="686"/>
        <source>Add occluder %1</source>
        <translation>Ajouter le masque d&apos;avant-plan %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="693"/>
        <source>There is no such occluder, or the stroke is empty.</source>
        <translation>Ce masque d&apos;avant-plan n&apos;existe pas, ou le trait est vide.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="699"/>
        <source>Add a stroke to occluder %1</source>
        <translation>Ajouter un trait au masque d&apos;avant-plan %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="710"/>
        <source>There is no such mark.</source>
        <translation>Ce repère n&apos;existe pas.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="717"/>
        <source>Delete light %1</source>
        <translation>Supprimer la lampe %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="718"/>
        <source>Delete shaft %1</source>
        <translation>Supprimer le rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="719"/>
        <source>Delete surface %1</source>
        <translation>Supprimer la surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="720"/>
        <source>Delete occluder %1</source>
        <translation>Supprimer le masque d&apos;avant-plan %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="800"/>
        <source>There is no such point.</source>
        <translation>Ce point n’existe pas.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="808"/>
        <location filename="../app/studio/document.cpp" line="826"/>
        <source>The outline would lose its area.</source>
        <translation>Le contour perdrait sa surface.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="809"/>
        <source>Reshape light %1</source>
        <translation>Remodeler la lumière %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="818"/>
        <source>Reshape shaft %1</source>
        <translation>Remodeler le rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="827"/>
        <source>Reshape surface %1</source>
        <translation>Remodeler la surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="835"/>
        <source>Reshape occluder %1</source>
        <translation>Remodeler l’occultant %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="851"/>
        <source>There is no such axis.</source>
        <translation>Cet axe n’existe pas.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="856"/>
        <source>Each line must be at least two pixels long.</source>
        <translation>Chaque ligne doit mesurer au moins deux pixels.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="860"/>
        <source>The two lines lie on one line: draw two different edges.</source>
        <translation>Les deux lignes sont sur une même droite : tracez deux arêtes différentes.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="869"/>
        <source>Draw the %1 vanishing lines</source>
        <translation>Tracer les lignes de fuite %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="870"/>
        <source>Forget the %1 vanishing lines</source>
        <translation>Oublier les lignes de fuite %1</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="884"/>
        <source>The room has no surface %1.</source>
        <translation>La pièce n’a pas de surface %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="887"/>
        <source>Unknown material.</source>
        <translation>Matériau inconnu.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="890"/>
        <source>The roughness must lie between 0 and 1.</source>
        <translation>La rugosité doit être comprise entre 0 et 1.</translation>
    </message>
    <message>
        <location filename="../app/studio/document.cpp" line="896"/>
        <source>Change the material of %1</source>
        <translation>Changer le matériau de %1</translation>
    </message>
</context>
<context>
    <name>inlay::studio::LayersDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="164"/>
        <source>Layers</source>
        <translation>Calques</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="165"/>
        <source>Composite</source>
        <translation>Composition</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="165"/>
        <source>Photo</source>
        <translation>Photo</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="166"/>
        <source>Albedo</source>
        <translation>Albédo</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="166"/>
        <source>Direct light</source>
        <translation>Lumière directe</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="167"/>
        <source>With objects</source>
        <translation>Avec les objets</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="167"/>
        <source>Without objects</source>
        <translation>Sans les objets</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="168"/>
        <source>Mask</source>
        <translation>Masque</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="168"/>
        <source>Difference</source>
        <translation>Différence</translation>
    </message>
</context>
<context>
    <name>inlay::studio::LibraryDock</name>
    <message>
        <source>Chair</source>
        <translation>Chaise</translation>
    </message>
    <message>
        <source>Armchair</source>
        <translation>Fauteuil</translation>
    </message>
    <message>
        <source>Sofa</source>
        <translation>Canapé</translation>
    </message>
    <message>
        <source>Coffee table</source>
        <translation>Table basse</translation>
    </message>
    <message>
        <source>Dining table</source>
        <translation>Table de salle à manger</translation>
    </message>
    <message>
        <source>Stool</source>
        <translation>Tabouret</translation>
    </message>
    <message>
        <source>Floor lamp</source>
        <translation>Lampadaire</translation>
    </message>
    <message>
        <source>Table lamp</source>
        <translation>Lampe de table</translation>
    </message>
    <message>
        <source>Vase</source>
        <translation>Vase</translation>
    </message>
    <message>
        <source>Potted plant</source>
        <translation>Plante en pot</translation>
    </message>
    <message>
        <source>Bookshelf</source>
        <translation>Étagère à livres</translation>
    </message>
    <message>
        <source>Rug</source>
        <translation>Tapis</translation>
    </message>
    <message>
        <source>Library</source>
        <translation>Bibliothèque de modèles</translation>
    </message>
    <message>
        <source>The model library could not be shown: %1</source>
        <translation>La bibliothèque de modèles ne peut pas être affichée : %1</translation>
    </message>
    <message>
        <source>%1
%2 × %3 × %4 m (width × depth × height)
Drag it into the photo.</source>
        <translation>%1
%2 × %3 × %4 m (largeur × profondeur × hauteur)
Faites-le glisser dans la photo.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::MainWindow</name>
    <message>
        <location filename="../app/studio/main_window.cpp" line="80"/>
        <source>Reading the photo</source>
        <translation>Lecture de la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="81"/>
        <source>Estimating the camera</source>
        <translation>Estimation de l&apos;appareil photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="82"/>
        <source>Fitting the room</source>
        <translation>Ajustement de la pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="83"/>
        <source>Estimating the lighting</source>
        <translation>Estimation de l&apos;éclairage</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="84"/>
        <source>Placing the objects</source>
        <translation>Placement des objets</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="387"/>
        <source>Samples per pixel of the shown composite</source>
        <translation>Échantillons par pixel de la composition affichée</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="388"/>
        <source>Samples per second of the renderer (millions)</source>
        <translation>Échantillons par seconde du rendu (millions)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="389"/>
        <source>Estimated error (RMSE in sRGB) where the objects change the photo</source>
        <translation>Erreur estimée (RMSE en sRGB) là où les objets modifient la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="390"/>
        <source>Render time since the last change</source>
        <translation>Temps de rendu depuis la dernière modification</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="391"/>
        <source>Zoom</source>
        <translation>Zoom</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="116"/>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="128"/>
        <source>Preparing the scene: %1…</source>
        <translation>Préparation de la scène : %1…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="354"/>
        <source>&amp;Open Scene…</source>
        <translation>&amp;Ouvrir une scène…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="375"/>
        <source>Open a scene file (.json)</source>
        <translation>Ouvrir un fichier de scène (.json)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="355"/>
        <source>Open &amp;Photo…</source>
        <translation>Ouvrir une &amp;photo…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="376"/>
        <source>Start a new scene from a photo</source>
        <translation>Commencer une nouvelle scène à partir d&apos;une photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="356"/>
        <source>Open &amp;Example</source>
        <translation>Ouvrir l&apos;&amp;exemple</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="357"/>
        <source>&amp;Save</source>
        <translation>&amp;Enregistrer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="358"/>
        <source>Save &amp;As…</source>
        <translation>Enregistrer &amp;sous…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="359"/>
        <source>&amp;Export Composite…</source>
        <translation>E&amp;xporter la composition…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="377"/>
        <source>Write the current composite as PNG, JPEG, TIFF or EXR</source>
        <translation>Écrire la composition actuelle en PNG, JPEG, TIFF ou EXR</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="360"/>
        <source>Export Shown &amp;Layer…</source>
        <translation>Exporter le &amp;calque affiché…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="378"/>
        <source>Write the layer the viewport shows (albedo, mask, …) as an 8-bit image</source>
        <translation>Écrire le calque affiché (albédo, masque, …) en image 8 bits</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="361"/>
        <source>Export Scene as &amp;glTF…</source>
        <translation>Exporter la scène en &amp;glTF…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="379"/>
        <source>Write the room, its lights, the camera and the objects as glTF 2.0, to go on in Blender</source>
        <translation>Écrire la pièce, ses lumières, la caméra et les objets en glTF 2.0, pour continuer dans Blender</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="362"/>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="414"/>
        <source>&amp;Undo</source>
        <translation>&amp;Annuler</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="415"/>
        <source>&amp;Redo</source>
        <translation>&amp;Rétablir</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="363"/>
        <source>Insert &amp;Sphere</source>
        <translation>Insérer une &amp;sphère</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="380"/>
        <source>Stand a sphere on the floor in the middle of the photo</source>
        <translation>Poser une sphère sur le sol au milieu de la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="364"/>
        <source>Insert &amp;Cube</source>
        <translation>Insérer un &amp;cube</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="381"/>
        <source>Stand a cube on the floor in the middle of the photo</source>
        <translation>Poser un cube sur le sol au milieu de la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="365"/>
        <source>&amp;Delete</source>
        <translation>&amp;Supprimer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="382"/>
        <source>Delete the selected object or mark</source>
        <translation>Supprimer l&apos;objet ou le repère sélectionné</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="366"/>
        <source>Zoom &amp;In</source>
        <translation>Zoom &amp;avant</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="367"/>
        <source>Zoom &amp;Out</source>
        <translation>Zoom a&amp;rrière</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="368"/>
        <source>&amp;Fit to Window</source>
        <translation>&amp;Ajuster à la fenêtre</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="369"/>
        <source>&amp;Before (Photo Only)</source>
        <translation>&amp;Avant (photo seule)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="383"/>
        <source>Toggle between the photo and the composite with the objects</source>
        <translation>Basculer entre la photo et la composition avec les objets</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="370"/>
        <source>&amp;Accept Estimated Box</source>
        <translation>Accepter la &amp;pièce estimée</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="384"/>
        <source>Keep the estimated back wall as yours</source>
        <translation>Garder le mur du fond estimé comme le vôtre</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="371"/>
        <source>Estimate the &amp;Box Again</source>
        <translation>Estimer à nouveau la &amp;pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="385"/>
        <source>Forget your corners of the back wall</source>
        <translation>Oublier vos coins du mur du fond</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="372"/>
        <source>&amp;Prepare the Scene Again</source>
        <translation>P&amp;réparer à nouveau la scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="386"/>
        <source>Estimate the camera, room and lighting again (after a cancel)</source>
        <translation>Estimer à nouveau l&apos;appareil photo, la pièce et l&apos;éclairage (après une annulation)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="373"/>
        <source>&amp;Vanishing Lines and Confidence</source>
        <translation>Lignes de &amp;fuite et confiance</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="392"/>
        <source>&amp;Select and Move</source>
        <translation>&amp;Sélectionner et déplacer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="392"/>
        <source>Outline a &amp;Light</source>
        <translation>Détourer une &amp;lampe</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="392"/>
        <source>Sun &amp;Shaft</source>
        <translation>Rayon de &amp;soleil</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="393"/>
        <source>&amp;Table Top or Step</source>
        <translation>Dessus de &amp;table ou marche</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="393"/>
        <source>&amp;Occluder Strokes</source>
        <translation>Traits de masque d&apos;&amp;avant-plan</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="374"/>
        <source>&amp;About Inlay</source>
        <translation>À &amp;propos d’Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="394"/>
        <source>&amp;Vanishing Lines (X, Y, Z)</source>
        <translation>&amp;Lignes de fuite (X, Y, Z)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="396"/>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="397"/>
        <source>Open &amp;Recent</source>
        <translation>Ouvrir un fichier &amp;récent</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="398"/>
        <source>&amp;Edit</source>
        <translation>&amp;Édition</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="399"/>
        <source>&amp;Tools</source>
        <translation>&amp;Outils</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="400"/>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="401"/>
        <source>&amp;Language</source>
        <translation>&amp;Langue</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="402"/>
        <source>System Default</source>
        <translation>Langue du système</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="403"/>
        <source>&amp;Help</source>
        <translation>A&amp;ide</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="404"/>
        <source>Main</source>
        <translation>Principale</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="414"/>
        <source>&amp;Undo %1</source>
        <translation>&amp;Annuler : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="415"/>
        <source>&amp;Redo %1</source>
        <translation>&amp;Rétablir : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="422"/>
        <location filename="../app/studio/main_window.cpp" line="431"/>
        <source>Preparing the scene…</source>
        <translation>Préparation de la scène…</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="422"/>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="423"/>
        <location filename="../app/studio/main_window.cpp" line="845"/>
        <source>Inlay</source>
        <translation>Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="447"/>
        <source>The scene could not be prepared</source>
        <translation>La scène n&apos;a pas pu être préparée</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/studio/main_window.cpp" line="456"/>
        <source>%1 (and %n more)</source>
        <translation>
            <numerusform>%1 (et %n autre)</numerusform>
            <numerusform>%1 (et %n autres)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="483"/>
        <source>– spp</source>
        <translation>– éch./px</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="484"/>
        <location filename="../app/studio/main_window.cpp" line="496"/>
        <source>– samples/s</source>
        <translation>– éch./s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="485"/>
        <source>error –</source>
        <translation>erreur –</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="486"/>
        <source>– s</source>
        <translation>– s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="490"/>
        <source>preview 1/%1</source>
        <translation>aperçu 1/%1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="491"/>
        <source>%1 spp, done</source>
        <translation>%1 éch./px, terminé</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="492"/>
        <source>%1 spp</source>
        <translation>%1 éch./px</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="493"/>
        <source>error %1</source>
        <translation>erreur %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="495"/>
        <source>%1 M samples/s</source>
        <translation>%1 M éch./s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="497"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="507"/>
        <source>%1 (new scene)</source>
        <translation>%1 (nouvelle scène)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="510"/>
        <source>Untitled</source>
        <translation>Sans titre</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="511"/>
        <source>%1[*] — Inlay</source>
        <translation>%1[*] — Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="530"/>
        <source>Cannot open</source>
        <translation>Ouverture impossible</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="530"/>
        <source>%1: no such file</source>
        <translation>%1 : fichier introuvable</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="536"/>
        <source>Cannot open the scene</source>
        <translation>Impossible d&apos;ouvrir la scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="555"/>
        <location filename="../app/studio/main_window.cpp" line="565"/>
        <source>Cannot open the example</source>
        <translation>Impossible d&apos;ouvrir l&apos;exemple</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="555"/>
        <source>The example scene is not installed.</source>
        <translation>La scène d&apos;exemple n&apos;est pas installée.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="565"/>
        <source>Cannot write %1</source>
        <translation>Impossible d&apos;écrire %1</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="575"/>
        <source>Open Scene</source>
        <translation>Ouvrir une scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="576"/>
        <source>Inlay scenes (*.json);;All files (*)</source>
        <translation>Scènes Inlay (*.json);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="583"/>
        <source>Open Photo</source>
        <translation>Ouvrir une photo</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="584"/>
        <source>Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;All files (*)</source>
        <translation>Photos (*.jpg *.jpeg *.png *.tif *.tiff *.exr *.hdr);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="591"/>
        <source>Cannot save the scene</source>
        <translation>Impossible d&apos;enregistrer la scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="595"/>
        <source>Saved %1</source>
        <translation>%1 enregistré</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="610"/>
        <source>Save Scene As</source>
        <translation>Enregistrer la scène sous</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="611"/>
        <source>Inlay scenes (*.json)</source>
        <translation>Scènes Inlay (*.json)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="619"/>
        <location filename="../app/studio/main_window.cpp" line="640"/>
        <location filename="../app/studio/main_window.cpp" line="669"/>
        <location filename="../app/studio/main_window.cpp" line="698"/>
        <source>Nothing to export</source>
        <translation>Rien à exporter</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="619"/>
        <location filename="../app/studio/main_window.cpp" line="640"/>
        <source>The composite has not been rendered yet.</source>
        <translation>La composition n&apos;a pas encore été rendue.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="623"/>
        <location filename="../app/studio/main_window.cpp" line="687"/>
        <source>PNG image (*.png)</source>
        <translation>Image PNG (*.png)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="623"/>
        <location filename="../app/studio/main_window.cpp" line="687"/>
        <source>JPEG image (*.jpg *.jpeg)</source>
        <translation>Image JPEG (*.jpg *.jpeg)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="624"/>
        <location filename="../app/studio/main_window.cpp" line="688"/>
        <source>TIFF image (*.tif *.tiff)</source>
        <translation>Image TIFF (*.tif *.tiff)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="624"/>
        <source>OpenEXR, linear (*.exr)</source>
        <translation>OpenEXR, linéaire (*.exr)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="625"/>
        <source>Export Composite</source>
        <translation>Exporter la composition</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="645"/>
        <source>Cannot export the composite</source>
        <translation>Impossible d&apos;exporter la composition</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="648"/>
        <source>Exported %1 (%2 spp)</source>
        <translation>%1 exporté (%2 éch./px)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="657"/>
        <source>glTF 2.0, separate files (*.gltf)</source>
        <translation>glTF 2.0, fichiers séparés (*.gltf)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="657"/>
        <source>glTF 2.0, binary (*.glb)</source>
        <translation>glTF 2.0, binaire (*.glb)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="658"/>
        <source>Export Scene as glTF</source>
        <translation>Exporter la scène en glTF</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="669"/>
        <source>The scene is not prepared yet.</source>
        <translation>La scène n’est pas encore préparée.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="675"/>
        <source>Cannot export the scene</source>
        <translation>Impossible d’exporter la scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="686"/>
        <source>Export Shown Layer</source>
        <translation>Exporter le calque affiché</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="698"/>
        <source>This layer has not been made yet.</source>
        <translation>Ce calque n&apos;a pas encore été calculé.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="705"/>
        <source>Cannot export the layer</source>
        <translation>Impossible d&apos;exporter le calque</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="706"/>
        <source>%1: cannot write (%2)</source>
        <translation>%1 : écriture impossible (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="678"/>
        <location filename="../app/studio/main_window.cpp" line="709"/>
        <source>Exported %1</source>
        <translation>%1 exporté</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="730"/>
        <source>About Inlay</source>
        <translation>À propos d’Inlay</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="731"/>
        <source>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Inserts synthetic objects into an ordinary photograph: a box room is fitted to the photo, its lights and reflectance are estimated, and a path tracer renders the objects into it (after Karsch et al., 2011).&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Inlay %1&lt;/h3&gt;&lt;p&gt;Insère des objets de synthèse dans une photographie ordinaire : une pièce en forme de boîte est ajustée à la photo, ses lampes et sa réflectance sont estimées, et un lancer de chemins y rend les objets (d’après Karsch et al., 2011).&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="740"/>
        <source>There is no floor in the middle of the photo to stand an object on.</source>
        <translation>Il n&apos;y a pas de sol au milieu de la photo où poser un objet.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="805"/>
        <source>a new scene</source>
        <translation>une nouvelle scène</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="808"/>
        <source>Restore unsaved work?</source>
        <translation>Restaurer le travail non enregistré ?</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="809"/>
        <source>Inlay did not close properly. Unsaved work on %1 was kept at %2. Restore it?</source>
        <translation>Inlay ne s&apos;est pas fermé correctement. Le travail non enregistré sur %1 a été conservé à %2. Le restaurer ?</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="813"/>
        <source>&amp;Restore</source>
        <translation>&amp;Restaurer</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="814"/>
        <source>&amp;Discard</source>
        <translation>&amp;Abandonner</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="832"/>
        <source>Cannot restore the unsaved work</source>
        <translation>Impossible de restaurer le travail non enregistré</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="838"/>
        <source>Restored the unsaved work.</source>
        <translation>Le travail non enregistré a été restauré.</translation>
    </message>
    <message>
        <location filename="../app/studio/main_window.cpp" line="845"/>
        <source>The scene has unsaved changes. Save them?</source>
        <translation>La scène a des modifications non enregistrées. Les enregistrer ?</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PrepareWorker</name>
    <message>
        <location filename="../app/studio/prepare_worker.cpp" line="98"/>
        <source>Internal error while preparing the scene.</source>
        <translation>Erreur interne pendant la préparation de la scène.</translation>
    </message>
</context>
<context>
    <name>inlay::studio::PropertiesDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="263"/>
        <source>Properties</source>
        <translation>Propriétés</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="273"/>
        <source>Surface:</source>
        <translation>Surface :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="274"/>
        <source>Finish:</source>
        <translation>Finition :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="275"/>
        <source>Roughness:</source>
        <translation>Rugosité :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="276"/>
        <source> m</source>
        <translation> m</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="277"/>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="278"/>
        <source>Diffuse</source>
        <translation>Diffus</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="278"/>
        <location filename="../app/studio/docks.cpp" line="283"/>
        <source>Glossy</source>
        <translation>Brillant</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="278"/>
        <location filename="../app/studio/docks.cpp" line="283"/>
        <source>Mirror</source>
        <translation>Miroir</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="278"/>
        <source>Metal</source>
        <translation>Métal</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="279"/>
        <source>Glass</source>
        <translation>Verre</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="279"/>
        <source>Frosted glass</source>
        <translation>Verre dépoli</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="279"/>
        <source>Emissive</source>
        <translation>Émissif</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="279"/>
        <source>From the file</source>
        <translation>Celui du fichier</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="281"/>
        <source>Reflectance of the object&apos;s surface</source>
        <translation>Réflectance de la surface de l&apos;objet</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="268"/>
        <source>Base (px):</source>
        <translation>Base (px) :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="269"/>
        <source>Height:</source>
        <translation>Hauteur :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="270"/>
        <source>Turn:</source>
        <translation>Rotation :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="271"/>
        <source>Material:</source>
        <translation>Matériau :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="272"/>
        <source>Colour:</source>
        <translation>Couleur :</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="282"/>
        <source>&lt;b&gt;Room surface&lt;/b&gt;</source>
        <translation>&lt;b&gt;Surface de la pièce&lt;/b&gt;</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="283"/>
        <source>Matte</source>
        <translation>Mat</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="285"/>
        <source>A real surface of the photo that reflects: a glossy floor, a mirror</source>
        <translation>Une vraie surface de la photo qui réfléchit : un sol brillant, un miroir</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="337"/>
        <source>No object selected</source>
        <translation>Aucun objet sélectionné</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="342"/>
        <source>&lt;b&gt;Object %1&lt;/b&gt; (%2)</source>
        <translation>&lt;b&gt;Objet %1&lt;/b&gt; (%2)</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="387"/>
        <source>Object colour</source>
        <translation>Couleur de l&apos;objet</translation>
    </message>
</context>
<context>
    <name>inlay::studio::SceneTreeDock</name>
    <message>
        <location filename="../app/studio/docks.cpp" line="31"/>
        <source>sphere</source>
        <translation>sphère</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="32"/>
        <source>cube</source>
        <translation>cube</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="79"/>
        <source>Scene</source>
        <translation>Scène</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="80"/>
        <source>Item</source>
        <translation>Élément</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="80"/>
        <source>Details</source>
        <translation>Détails</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="84"/>
        <source>Room</source>
        <translation>Pièce</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="87"/>
        <source>%1 × %2 m, %3 m high</source>
        <translation>%1 × %2 m, %3 m de haut</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="92"/>
        <source>back wall given</source>
        <translation>mur du fond donné</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="92"/>
        <source>estimated</source>
        <translation>estimée</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="95"/>
        <source>Lights</source>
        <translation>Lampes</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="98"/>
        <source>Light %1</source>
        <translation>Lampe %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="99"/>
        <source>outline on the photo</source>
        <translation>contour sur la photo</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="100"/>
        <source>rectangle in 3D</source>
        <translation>rectangle en 3D</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="114"/>
        <source>Shafts</source>
        <translation>Rayons de soleil</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="114"/>
        <source>Shaft %1</source>
        <translation>Rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="115"/>
        <source>sunlit patch and its window</source>
        <translation>tache de soleil et sa fenêtre</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="116"/>
        <source>Surfaces</source>
        <translation>Surfaces</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="116"/>
        <source>Surface %1</source>
        <translation>Surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="118"/>
        <source>Occluders</source>
        <translation>Masques d&apos;avant-plan</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="118"/>
        <source>Occluder %1</source>
        <translation>Masque d&apos;avant-plan %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="120"/>
        <source>%1 strokes in front, %2 behind</source>
        <translation>%1 traits devant, %2 derrière</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="125"/>
        <source>Objects</source>
        <translation>Objets</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="129"/>
        <source>Object %1</source>
        <translation>Objet %1</translation>
    </message>
    <message>
        <location filename="../app/studio/docks.cpp" line="130"/>
        <source>%1, %2 m</source>
        <translation>%1, %2 m</translation>
    </message>
</context>
<context>
    <name>inlay::studio::Viewport</name>
    <message>
        <location filename="../app/studio/viewport.cpp" line="303"/>
        <source>Drag an object or a corner of the back wall.</source>
        <translation>Faites glisser un objet ou un coin du mur du fond.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="305"/>
        <source>Click around a light; click the first point (or press Enter) to close.</source>
        <translation>Cliquez autour d’une lampe ; cliquez sur le premier point (ou appuyez sur Entrée) pour fermer.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="307"/>
        <source>Now drag a box around the window the sunlight comes through.</source>
        <translation>Tracez maintenant un cadre autour de la fenêtre par où entre le soleil.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="308"/>
        <source>Drag a box around the patch of sunlight.</source>
        <translation>Tracez un cadre autour de la tache de soleil.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="311"/>
        <source>Click the floor straight below the first point of the outline.</source>
        <translation>Cliquez sur le sol juste en dessous du premier point du contour.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="312"/>
        <source>Click around the top of a table or step; click the first point to close.</source>
        <translation>Cliquez autour du dessus d&apos;une table ou d&apos;une marche ; cliquez sur le premier point pour fermer.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="314"/>
        <source>Left drag over the thing in front, right drag over what is behind it; Enter starts another occluder.</source>
        <translation>Glissez avec le bouton gauche sur ce qui est devant, avec le droit sur ce qui est derrière ; Entrée commence un autre masque.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="319"/>
        <source>Drag along an edge that runs in the %1 direction (keys X, Y, Z choose it).</source>
        <translation>Faites glisser le long d’une arête dans la direction %1 (les touches X, Y, Z la choisissent).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="320"/>
        <source>Now drag along a second edge in the %1 direction.</source>
        <translation>Faites maintenant glisser le long d’une deuxième arête dans la direction %1.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="392"/>
        <source>Back wall (yours)</source>
        <translation>Mur du fond (le vôtre)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="392"/>
        <source>Back wall (estimated)</source>
        <translation>Mur du fond (estimé)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="448"/>
        <source>%1 px</source>
        <translation>%1 px</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="486"/>
        <source>%1: %2 px</source>
        <translation>%1 : %2 px</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="515"/>
        <source>Light %1</source>
        <translation>Lampe %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="529"/>
        <source>Shaft %1</source>
        <translation>Rayon de soleil %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="544"/>
        <source>Surface %1</source>
        <translation>Surface %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="696"/>
        <source>Preparing the scene…</source>
        <translation>Préparation de la scène…</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="699"/>
        <source>The scene could not be prepared: %1</source>
        <translation>La scène n&apos;a pas pu être préparée : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="703"/>
        <source>Open a scene or a photo (File menu).</source>
        <translation>Ouvrez une scène ou une photo (menu Fichier).</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="706"/>
        <source>Before: the photo without objects</source>
        <translation>Avant : la photo sans les objets</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="724"/>
        <source>Vanishing points: x %1, y %2, z %3 (confidence)</source>
        <translation>Points de fuite : x %1, y %2, z %3 (confiance)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="728"/>
        <source>Focal length %1 px (%2–%3 px)</source>
        <translation>Focale %1 px (%2–%3 px)</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="769"/>
        <source>An outline needs at least three points.</source>
        <translation>Un contour demande au moins trois points.</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="909"/>
        <location filename="../app/studio/viewport.cpp" line="1051"/>
        <source>Cannot place the object here: %1</source>
        <translation>Impossible de placer l&apos;objet ici : %1</translation>
    </message>
    <message>
        <location filename="../app/studio/viewport.cpp" line="983"/>
        <source>Each line must be at least two pixels long.</source>
        <translation>Chaque ligne doit mesurer au moins deux pixels.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/studio/main.cpp" line="47"/>
        <source>Insert synthetic objects into a photograph.</source>
        <translation>Insérer des objets de synthèse dans une photographie.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="52"/>
        <source>A scene file (.json) or a photo; none: the example.</source>
        <translation>Un fichier de scène (.json) ou une photo ; aucun : l&apos;exemple.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="56"/>
        <source>Grab the window to &lt;file&gt; once rendered, then exit.</source>
        <translation>Capturer la fenêtre dans &lt;file&gt; une fois rendue, puis quitter.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="60"/>
        <source>Samples per pixel to wait for (default 4).</source>
        <translation>Échantillons par pixel à attendre (4 par défaut).</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="64"/>
        <source>Restore unsaved work left by a crash without asking.</source>
        <translation>Restaurer sans demander le travail non enregistré laissé par un plantage.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="79"/>
        <source>Give at most one file.</source>
        <translation>Donnez au plus un fichier.</translation>
    </message>
    <message>
        <location filename="../app/studio/main.cpp" line="86"/>
        <source>expected a number &gt;= 0</source>
        <translation>un nombre &gt;= 0 est attendu</translation>
    </message>
</context>
</TS>
